#pragma once
// Everything a run accumulates, and how it is written into the output folder.
#include <vlo/core/bounded_sample.h>
#include <vlo/core/frame.h>
#include <vlo/io/trajectory.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/motion_source.h>
#include <vlo/pipeline/pipeline_options.h>
#include <vlo/pipeline/run.h>

#include <optional>
#include <string>
#include <vector>

namespace vlo
{
struct RunOutputs
{
	RunPlan plan;
	FrameTable table;
	Trajectory lidar;  ///< the LiDAR odometry's (trajectory_lo.tum or trajectory_vlo.tum), vehicle frame
	const MotionSource* motion_source = nullptr;  ///< its path is trajectory_vo.tum; draws its own snapshots
	PointCloud map;  ///< vehicle frame of the first frame (already thinned)
	/// KITTI's camera 0 on the vehicle, when known: each trajectory is also written as KITTI poses.
	std::optional<Eigen::Isometry3d> cam0_T_vehicle;
	/// For projected-scan snapshots: at most 24 (3 MB each for KITTI) over the whole drive.
	BoundedSample<Frame> sample_frames{24};

	void addSampleFrame(const Frame& f);
	/// Writes trajectories (trajectory_<name>.tum, and .kitti.txt with cam0_T_vehicle), frames.csv, map.pcd, run.ini and snapshots/; returns the summary figures.
	RunSummary write(const std::string& dir, const PipelineOptions& opt, const std::string& effectiveIni,
		const std::string& gtPath) const;
};

/// summary.json: mode, frames, timing, path length, largest step, reader statistics, inputs, the per-stage timings.
void writeSummaryJson(const std::string& path, const RunSummary& s, const RunRequest& req);
}  // namespace vlo
