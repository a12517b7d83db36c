#pragma once
// The end-of-run table of times per stage, from frames.csv's timing columns (ms_*): every module
// times its stages with the core stopwatch (vlo/core/stopwatch.h) into those columns, so the table
// is what frames.csv holds, summarised.
#include <vlo/kernel/frame_table.h>

#include <string>
#include <vector>

namespace vlo::pipeline
{
struct StageTiming
{
	std::string stage;  ///< the column, e.g. ms_lo_mapping
	std::size_t count = 0;  ///< frames in which the stage ran
	double mean = 0, p95 = 0, max = 0;  ///< ms; p95 by nearest rank
};

/// One entry per ms_* column, in frames.csv's order (ms_total last); empty cells are not counted.
std::vector<StageTiming> stageTimings(const kernel::FrameTable& table);

/// A fixed-width table, one stage a line, with a header.
std::string formatStageTimings(const std::vector<StageTiming>& timings);
}  // namespace vlo::pipeline
