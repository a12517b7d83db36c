#pragma once
// The time-per-stage plot of a run: frames.csv's ms_* columns stacked per frame.
#include <string>
#include <vector>

namespace vlo::viz
{
/// One frames.csv time column (e.g. "ms_vo_extract") with its value per frame (NaN: the stage did not run).
struct StageTimeColumn
{
	std::string name;
	std::vector<double> ms;
};

/// Draws each frame's stage times stacked (a stage with sub-stages, e.g. ms_vo beside ms_vo_extract, by its
/// sub-stages; ms_total's remainder on top as "other"), with the 100 ms budget of a 10 Hz sensor dashed.
/// `columns` are the ms_* columns in frames.csv's order, ms_total among them. Nothing when there is no stage.
void writeStageTimePlot(const std::string& png, const std::vector<double>& frame,
	const std::vector<StageTimeColumn>& columns);
}  // namespace vlo::viz
