#include <vlo/viz/series.h>
#include <vlo/viz/stage_time_plot.h>

#include <algorithm>
#include <cmath>

namespace vlo::viz
{
namespace
{
constexpr double kBudgetMs = 100;  ///< one frame of a 10 Hz LiDAR
}

void writeStageTimePlot(const std::string& png, const std::vector<double>& frame,
	const std::vector<StageTimeColumn>& columns)
{
	std::vector<Series> stacked;
	std::vector<double> sum(frame.size(), 0.0);
	auto add = [&](const std::string& name, const std::vector<double>& ms) {
		Series s;
		s.name = name;
		s.x = frame;
		s.fill = true;
		for (std::size_t i = 0; i < frame.size(); ++i)
		{
			sum[i] += std::isfinite(ms[i]) ? ms[i] : 0.0;  // a stage that did not run took no time
			s.y.push_back(sum[i]);
		}
		stacked.push_back(std::move(s));
	};
	// A stage with sub-stages (ms_vo beside ms_vo_extract, ...) is their sum: only the sub-stages are stacked,
	// and its own overhead goes to "other".
	const auto hasParts = [&](const std::string& c) {
		return std::any_of(columns.begin(), columns.end(),
			[&](const StageTimeColumn& d) { return d.name.rfind(c + "_", 0) == 0; });
	};
	const std::vector<double>* total = nullptr;
	for (const auto& c : columns)
	{
		if (c.name == "ms_total") total = &c.ms;
		else if (c.name.rfind("ms_", 0) == 0 && !hasParts(c.name) && c.ms.size() == frame.size())
			add(c.name.substr(3), c.ms);
	}
	if (stacked.empty() || !total || total->size() != frame.size()) return;
	std::vector<double> other(frame.size());
	for (std::size_t i = 0; i < frame.size(); ++i) other[i] = std::max(0.0, (*total)[i] - sum[i]);
	add("other (undistortion, map, untimed)", other);  // ms_total holds no reading (doc/FORMATS.md)
	stacked.back().color = Rgb{170, 170, 170};  // not a stage: neutral, and never a palette colour again
	const double top = *std::max_element(sum.begin(), sum.end());
	SeriesStyle style;
	style.title = "Time per frame per stage, stacked (dashed: the 100 ms budget of a 10 Hz sensor)";
	style.xlabel = "frame";
	style.ylabel = "time [ms]";
	style.ymin = 0;
	style.reference_y = kBudgetMs;
	style.ymax = 1.05 * std::max(top, kBudgetMs);
	style.legend_outside = true;  // up to a dozen stages: inside, the legend would hide the top of the stack
	style.width = 1500;  // the plot keeps its width beside the legend
	renderSeries(stacked, png, style);
}
}  // namespace vlo::viz
