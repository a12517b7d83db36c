#pragma once
// report.md in a vlo-run folder: the summary table, the accuracy against --gt when given, and every
// snapshot and plot of the folder embedded with relative links, readable in any Markdown viewer.
#include <vlo/kernel/frame_table.h>
#include <vlo/pipeline/run.h>

#include <string>
#include <vector>

namespace vlo::pipeline
{
/// snapshots/time_per_stage.png from the table's ms_* columns (vlo/viz/stage_time_plot.h); nothing when the
/// table has no stage time.
void writeStageTimePlot(const std::string& png, const kernel::FrameTable& table);

/// The Markdown of the report; `files` are the folder's files (relative paths) that it may link to.
std::string runReportMarkdown(const RunSummary& s, const RunRequest& req, const std::vector<std::string>& files,
	const std::string& accuracy);

/// Evaluates the final trajectory against req.gt (when given; accuracy plots into snapshots/ when
/// `plots`), draws the stage-time plot (when `plots`) and writes DIR/report.md atomically, linking
/// only files that exist in DIR.
void writeRunReport(const std::string& dir, const RunSummary& s, const RunRequest& req, const kernel::FrameTable& table, bool plots);
}  // namespace vlo::pipeline
