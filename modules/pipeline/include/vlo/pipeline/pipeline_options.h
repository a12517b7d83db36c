#pragma once
// The [pipeline] section: which modules run, how observations are paired, what is written.
#include <vlo/core/option_table.h>
#include <vlo/kernel/motion_source.h>

#include <string>

namespace vlo::pipeline
{
/// What a run does, decided from the mode in this one place: frame -> motion source -> LiDAR
/// odometry -> outputs, with either stage left out.
struct RunPlan
{
	std::string name;  ///< lo | vo | vlo: the final trajectory is trajectory_<name>.tum
	std::string motion_source;  ///< registry name; empty = none (mode lo)
	bool lidar_odometry = false;  ///< false in mode vo
	bool bootstrapping = false;  ///< the motion source's motion is the LiDAR odometry's initial guess
	std::string lidar_label;  ///< name of the LiDAR odometry's trajectory in plots
};

struct PipelineOptions : public OptionSet
{
	std::string mode = "lo";  ///< lo (LiDAR only, the A-LOAM baseline) | vo | vlo
	std::string lidar_odometry = "aloam";  ///< registry name of the LiDAR odometry module
	std::string visual_odometry = "orb";  ///< registry name of the visual odometry module
	std::string scale_correction = "lidar_depth";  ///< registry name of the scale-correction module
	/// Registry name of the motion source of mode vlo (mode vo: the VO alone, "visual").
	std::string motion_source = "metric_mono";
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
	int scale_snapshot_every = 0;
	/// Modes lo and vlo: close loops over the LiDAR odometry ([loop]); trajectory_slam.tum and map.pcd
	/// from the corrected poses, the odometry's own trajectory unchanged beside it.
	bool loop_closure = false;  ///< mode vlo: a scale-corrector snapshot every N frames (0 = none)
	/// 1: everything on one thread; 2: frames read ahead on a thread, and the LiDAR odometry on another,
	/// up to 3 frames behind the motion source; auto: 2 when the process may use two cores or more.
	/// The outputs are the same whatever the count: the motion source never reads the LiDAR odometry's results.
	std::string threads = "auto";

	/// The count `threads` stands for: 1 or 2.
	int threadCount() const;

	RunPlan plan() const;
	/// The module names a motion source composes.
	kernel::MotionSourceSetup motionSourceSetup() const
	{
		return {visual_odometry, scale_correction, scale_snapshot_every, threadCount()};
	}

   protected:
	void declare(OptionTable& t) override;
};
}  // namespace vlo::pipeline
