#include <vlo/pipeline/pipeline_options.h>

#include <sched.h>

#include <thread>

namespace vlo::pipeline
{
void PipelineOptions::declare(OptionTable& t)
{
	t.add("mode", mode, "lo | vo | vlo", "lo = LiDAR odometry alone (A-LOAM baseline); vo = camera only; vlo = full");
	t.add("lidar_odometry", lidar_odometry, "any", "LiDAR odometry module (registry name)");
	t.add("visual_odometry", visual_odometry, "any", "visual odometry module (registry name)");
	t.add("scale_correction", scale_correction, "any", "scale-correction module of a monocular VO (registry name)");
	t.add("motion_source", motion_source, "any", "vlo: LiDAR odometry's initial guess: metric_mono = VO + scale correction; visual = VO alone");
	t.add("camera_label", camera_label, "any", "sensor label of the camera observations");
	t.add("lidar_label", lidar_label, "any", "sensor label of the LiDAR observations");
	t.add("max_time_diff", max_time_diff, "> 0", "[s] largest time difference of a paired image and scan");
	t.add("max_frames", max_frames, ">= 0", "stop after this many frames (0 = all)");
	t.add("map_voxel", map_voxel, "> 0", "[m] voxel size of map.pcd");
	t.add("map_every", map_every, ">= 0", "add every N-th scan to map.pcd (0 = no map.pcd)");
	t.add("map_max_range", map_max_range, "> 0", "[m] scan points farther from the sensor are left out of map.pcd");
	t.add("snapshots", snapshots, "true | false", "write snapshots/ at the end of the run");
	t.add("sample_frame_every", sample_frame_every, ">= 0", "projected-scan snapshot every N frames (0 = none)");
	t.add("bootstrapping", bootstrapping, "true | false", "vlo: scale-corrected VO motion as LOAM's initial guess (false = A-LOAM)");
	t.add("scale_snapshot_every", scale_snapshot_every, ">= 0", "vlo: scale-corrector snapshot every N frames (0 = none)");
	t.add("loop_closure", loop_closure, "true | false", "lo, vlo: close loops ([loop]): trajectory_slam.tum, map.pcd from its poses");
	t.add("threads", threads, "1 | 2 | auto", "1 = one thread; 2 = read ahead, and LiDAR odometry up to 3 frames behind the motion source; auto = 2 with 2+ usable cores. Same outputs");
}

int PipelineOptions::threadCount() const
{
	if (threads != "auto") return threads == "2" ? 2 : 1;
	// The cores this process may run on (taskset, cgroup cpusets), not those of the machine.
	cpu_set_t cores;
	const int usable = sched_getaffinity(0, sizeof(cores), &cores) == 0 ? CPU_COUNT(&cores)
																		: static_cast<int>(std::thread::hardware_concurrency());
	return usable >= 2 ? 2 : 1;
}

RunPlan PipelineOptions::plan() const
{
	if (mode == "lo") return {"lo", "", true, false, "LiDAR odometry"};
	if (mode == "vo") return {"vo", "visual", false, false, ""};
	return {"vlo", motion_source, true, bootstrapping, "VLO"};
}
}  // namespace vlo::pipeline
