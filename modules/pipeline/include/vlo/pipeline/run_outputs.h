#pragma once
// Everything a run accumulates, and how it is written into the output folder.
#include <vlo/core/bounded_sample.h>
#include <vlo/core/frame.h>
#include <vlo/io/trajectory.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/motion_source.h>
#include <vlo/loop/loop_closure.h>
#include <vlo/pipeline/pipeline_options.h>
#include <vlo/pipeline/run.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vlo::pipeline
{
struct RunOutputs
{
	RunPlan plan;
	kernel::FrameTable table;
	Trajectory lidar;  ///< the LiDAR odometry's (trajectory_lo.tum or trajectory_vlo.tum), vehicle frame
	Trajectory motion;  ///< the motion source's (trajectory_vo.tum), vehicle frame; see setMotion
	std::string motion_label;  ///< its name in plots
	/// With [pipeline] loop_closure: the odometry's poses corrected by the pose graph (trajectory_slam.tum),
	/// one per pose of `lidar`, and every loop candidate verified.
	Trajectory slam;
	std::vector<loop::LoopRecord> loops;
	std::vector<std::pair<std::string, double>> figures;  ///< the motion source's and loop closure's counts for summary.json
	PointCloud map;  ///< vehicle frame of the first frame (already thinned)
	/// KITTI's camera 0 on the vehicle, when known: each trajectory is also written as KITTI poses.
	std::optional<Eigen::Isometry3d> cam0_T_vehicle;
	/// For projected-scan snapshots: at most 24 (3 MB each for KITTI) over the whole drive.
	BoundedSample<Frame> sample_frames{24};

	void addSampleFrame(const Frame& f);
	/// After the frame loop: the motion source's trajectory up to the table's last row (with two threads a
	/// run stopped early may have it a few frames further), its label and figures.
	void setMotion(const kernel::MotionSource& source);
	/// After the loop closure's finish(): its trajectory, its loops in the rows of their frames
	/// (loop_* columns) and its counts.
	void setLoops(const loop::LoopClosure& closure);
	/// Per pose of `lidar`: slam * lidar^-1, the correction of the world the loop closure made there.
	std::vector<Eigen::Isometry3d> loopCorrections() const;
	/// The table's row of a frame index; in modes lo and vlo also its pose's index in `lidar`.
	std::optional<std::size_t> frameRow(long long frame) const;
	/// Writes trajectories (trajectory_<name>.tum, and .kitti.txt with cam0_T_vehicle), frames.csv, map.pcd
	/// and run.ini; returns the summary figures.
	RunSummary write(const std::string& dir, const std::string& effectiveIni) const;
};

/// snapshots/ of DIR (viz's run snapshots, then the motion source's own when there is one): a convenience, so
/// a failure to render is logged, not fatal; a bad --gt file still throws InputError.
void writeSnapshots(const std::string& dir, const RunOutputs& o, const kernel::MotionSource* motion, const std::string& gtPath);

/// summary.json: mode, frames, timing, path length, largest step, reader statistics, inputs, the per-stage timings.
void writeSummaryJson(const std::string& path, const RunSummary& s, const RunRequest& req);
}  // namespace vlo::pipeline
