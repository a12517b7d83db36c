#pragma once
// The [pipeline] section: which estimators run, how observations are paired, what is written.
#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace vlo
{
struct PipelineOptions : public mrpt::config::CLoadableOptions
{
	std::string mode = "lo";  ///< lo (LiDAR only, the A-LOAM baseline) | vo | vlo
	std::string lidar_odometry = "aloam";  ///< registry name of the LiDAR odometry module
	std::string visual_odometry = "orb";  ///< registry name of the visual odometry module
	std::string camera_label = "CAMERA";
	std::string lidar_label = "LIDAR";
	double max_time_diff = 0.05;  ///< [s] between a paired image and scan
	int max_frames = 0;  ///< stop after this many frames; 0 = all
	double map_voxel = 0.2;  ///< [m] voxel size of map.pcd
	int map_every = 5;  ///< add every N-th scan to map.pcd (0 = no map.pcd)
	double map_max_range = 60;  ///< [m] scan points farther from the sensor are left out of map.pcd
	bool snapshots = true;  ///< write snapshots/ at the end of the run
	int sample_frame_every = 0;  ///< also a projected-scan snapshot every N frames (0 = none)
	/// Mode vlo: the scale-corrected VO motion is LOAM's initial guess (false: constant velocity, the
	/// A-LOAM baseline inside a vlo run, for the ablation).
	bool bootstrapping = true;
	int scale_snapshot_every = 0;  ///< mode vlo: a scale-corrector snapshot every N frames (0 = none)

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
	void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
	/// Throws InputError naming the key for an impossible value.
	void validate(const std::string& origin) const;

	bool needsCamera() const { return mode != "lo"; }
	bool needsLidar() const { return mode != "vo"; }
};
}  // namespace vlo
