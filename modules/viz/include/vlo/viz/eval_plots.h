#pragma once
// The pictures of `vlo-eval --plots`: the KITTI devkit's four error plots (translation and rotation
// error against path length and against speed) with one curve per estimate on shared axes, and each
// estimate's path seen from above coloured by its absolute trajectory error (as `evo_ape --plot`).
#include <vlo/eval/evaluate.h>
#include <vlo/viz/series.h>

#include <string>
#include <vector>

namespace vlo::viz
{
struct EvalRun
{
	std::string name;  ///< legend name, e.g. the estimate's file name without extension
	eval::EvalReport report;
};

struct PlotSpec
{
	std::string file;  ///< file name in the plot folder
	std::vector<Series> series;  ///< the numbers the picture is drawn from
	SeriesStyle style;
};

/// The devkit's four plots, one series per run (runs without a curve point keep their legend entry and
/// draw nothing). A plot that no run has a point for is left out; none when no run has a KITTI result.
/// Units as the devkit's: %, deg/m, m, km/h.
std::vector<PlotSpec> kittiErrorPlots(const std::vector<EvalRun>& runs);

/// "ate_<name>.png" for a run, with characters other than letters, digits, '-', '_' and '.' as '_'.
std::string atePlotFile(const std::string& run_name);

/// Writes the devkit plots and, for each run with an ATE, its coloured top-down view into `dir`
/// (created when missing), each PNG complete or absent. Returns the file names written, in order.
std::vector<std::string> writeEvalPlots(const std::string& dir, const std::vector<EvalRun>& runs);
}  // namespace vlo::viz
