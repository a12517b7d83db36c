#pragma once
// One replay of a rawlog through the configured estimators, and everything it leaves in the output
// folder: trajectories, frames.csv, map.pcd, run.ini, summary.json and snapshots/.
#include <vlo/pipeline/stage_timings.h>

#include <string>
#include <utility>
#include <vector>

namespace vlo::pipeline
{
struct RunRequest
{
	std::string rawlog, ini, out;
	std::vector<std::string> overrides;  ///< "section.key=value"
	std::string gt;  ///< optional ground truth TUM, used only to draw snapshots
	std::string kitti_calib = {};  ///< optional KITTI calib.txt: its Tr places camera 0 (else the rawlog's note, if any)
	bool overwrite = false;  ///< replace the run that `out` holds (RunFolder)
};

struct RunSummary
{
	std::string mode;
	std::size_t frames = 0;
	double seconds = 0;  ///< wall time of the frame loop
	double ms_per_frame = 0;
	double path_length_m = 0;  ///< of the final trajectory
	double max_step_m = 0;  ///< largest frame-to-frame translation of the final trajectory
	std::string final_trajectory;  ///< file name inside the output folder
	std::string slam_trajectory;  ///< trajectory_slam.tum with [pipeline] loop_closure, else empty
	/// False when the run stopped before the end of its input (Ctrl-C, a rawlog cut short): its outputs are
	/// those of the frames up to last_frame, and stop_reason says why.
	bool complete = true;
	std::string stop_reason;
	long long last_frame = -1;  ///< index of the last frame in frames.csv
	std::string reader_stats;
	std::vector<std::pair<std::string, double>> figures;  ///< mode-specific counts for summary.json
	std::vector<StageTiming> stage_timings;  ///< per ms_* column of frames.csv, for summary.json and the log
};

/// Throws InputError for bad input (files, options, data); nothing is left half-written. A run that stops
/// early, on Ctrl-C (Interrupted) or input that fails after its first frames (InputError), first writes
/// the outputs of the frames it computed, with summary.json's "complete": false, then throws saying so.
RunSummary runPipeline(const RunRequest& request);
}  // namespace vlo::pipeline
