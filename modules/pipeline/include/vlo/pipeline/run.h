#pragma once
// One replay of a rawlog through the configured estimators, and everything it leaves in the output
// folder: trajectories, frames.csv, map.pcd, run.ini, summary.json and snapshots/.
#include <vlo/pipeline/stage_timings.h>

#include <string>
#include <utility>
#include <vector>

namespace vlo
{
struct RunRequest
{
	std::string rawlog, ini, out;
	std::vector<std::string> overrides;  ///< "section.key=value"
	std::string gt;  ///< optional ground truth TUM, used only to draw snapshots
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
	std::string reader_stats;
	std::vector<std::pair<std::string, double>> figures;  ///< mode-specific counts for summary.json
	std::vector<StageTiming> stage_timings;  ///< per ms_* column of frames.csv, for summary.json and the log
};

/// Throws InputError for bad input (files, options, data); nothing is left half-written.
RunSummary runPipeline(const RunRequest& request);
}  // namespace vlo
