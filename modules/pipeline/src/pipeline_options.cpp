#include <mrpt/config/CConfigFileBase.h>
#include <vlo/core/error.h>
#include <vlo/pipeline/pipeline_options.h>

namespace vlo
{
void PipelineOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	MRPT_LOAD_CONFIG_VAR(mode, string, c, s);
	MRPT_LOAD_CONFIG_VAR(lidar_odometry, string, c, s);
	MRPT_LOAD_CONFIG_VAR(visual_odometry, string, c, s);
	MRPT_LOAD_CONFIG_VAR(scale_correction, string, c, s);
	MRPT_LOAD_CONFIG_VAR(motion_source, string, c, s);
	MRPT_LOAD_CONFIG_VAR(camera_label, string, c, s);
	MRPT_LOAD_CONFIG_VAR(lidar_label, string, c, s);
	MRPT_LOAD_CONFIG_VAR(max_time_diff, double, c, s);
	MRPT_LOAD_CONFIG_VAR(max_frames, int, c, s);
	MRPT_LOAD_CONFIG_VAR(map_voxel, double, c, s);
	MRPT_LOAD_CONFIG_VAR(map_every, int, c, s);
	MRPT_LOAD_CONFIG_VAR(map_max_range, double, c, s);
	MRPT_LOAD_CONFIG_VAR(snapshots, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(sample_frame_every, int, c, s);
	MRPT_LOAD_CONFIG_VAR(bootstrapping, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(scale_snapshot_every, int, c, s);
}

void PipelineOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(mode, "lo = LiDAR odometry alone (A-LOAM baseline); vo = camera only; vlo = full");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lidar_odometry, "LiDAR odometry module (registry name)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(visual_odometry, "visual odometry module (registry name)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(scale_correction, "scale-correction module of a monocular VO (registry name)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(motion_source, "vlo: LiDAR odometry's initial guess: metric_mono = VO + scale correction; visual = VO alone");
	MRPT_SAVE_CONFIG_VAR_COMMENT(camera_label, "sensor label of the camera observations");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lidar_label, "sensor label of the LiDAR observations");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_time_diff, "[s] largest time difference of a paired image and scan");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_frames, "stop after this many frames (0 = all)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(map_voxel, "[m] voxel size of map.pcd");
	MRPT_SAVE_CONFIG_VAR_COMMENT(map_every, "add every N-th scan to map.pcd (0 = no map.pcd)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(map_max_range, "[m] scan points farther from the sensor are left out of map.pcd");
	MRPT_SAVE_CONFIG_VAR_COMMENT(snapshots, "write snapshots/ at the end of the run");
	MRPT_SAVE_CONFIG_VAR_COMMENT(sample_frame_every, "projected-scan snapshot every N frames (0 = none)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(bootstrapping, "vlo: scale-corrected VO motion as LOAM's initial guess (false = A-LOAM)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(scale_snapshot_every, "vlo: scale-corrector snapshot every N frames (0 = none)");
}

void PipelineOptions::validate(const std::string& origin) const
{
	if (mode != "lo" && mode != "vo" && mode != "vlo")
		failInput(origin + ": [pipeline] mode", "must be lo, vo or vlo, got '" + mode + "'");
	if (max_time_diff <= 0) failInput(origin + ": [pipeline] max_time_diff", "must be > 0");
	if (max_frames < 0) failInput(origin + ": [pipeline] max_frames", "must be >= 0");
	if (map_voxel <= 0) failInput(origin + ": [pipeline] map_voxel", "must be > 0");
	if (map_every < 0) failInput(origin + ": [pipeline] map_every", "must be >= 0");
	if (map_max_range <= 0) failInput(origin + ": [pipeline] map_max_range", "must be > 0");
	if (sample_frame_every < 0) failInput(origin + ": [pipeline] sample_frame_every", "must be >= 0");
	if (scale_snapshot_every < 0) failInput(origin + ": [pipeline] scale_snapshot_every", "must be >= 0");
}

RunPlan PipelineOptions::plan() const
{
	if (mode == "lo") return {"lo", "", true, false, "LiDAR odometry"};
	if (mode == "vo") return {"vo", "visual", false, false, ""};
	return {"vlo", motion_source, true, bootstrapping, "VLO"};
}
}  // namespace vlo
