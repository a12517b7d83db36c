#pragma once
// Everything a run accumulates, and how it is written into the output folder.
#include <vlo/core/frame.h>
#include <vlo/io/trajectory.h>
#include <vlo/pipeline/frame_table.h>
#include <vlo/pipeline/pipeline_options.h>
#include <vlo/pipeline/run.h>
#include <vlo/pipeline/scale_stage.h>

#include <string>
#include <vector>

namespace vlo
{
struct RunOutputs
{
	std::string mode;
	FrameTable table;
	Trajectory lo;  ///< LiDAR odometry (mode lo) or the final VLO trajectory (mode vlo), vehicle frame
	Trajectory vo;  ///< visual odometry (tracked frames only; metric in mode vlo), vehicle frame
	PointCloud map;  ///< vehicle frame of the first frame (already thinned)
	std::vector<Frame> sample_frames;  ///< for projected-scan snapshots
	std::vector<ScaleSnapshot> scale_snapshots;  ///< mode vlo: frames with a scale estimate to draw

	void addSampleFrame(const Frame& f);
	/// Writes trajectories, frames.csv, map.pcd, run.ini and snapshots/; returns the summary figures.
	RunSummary write(const std::string& dir, const PipelineOptions& opt, const std::string& effectiveIni,
		const std::string& gtPath) const;
};

/// summary.json: mode, frames, timing, path length, largest step, reader statistics, inputs.
void writeSummaryJson(const std::string& path, const RunSummary& s, const RunRequest& req);
}  // namespace vlo
