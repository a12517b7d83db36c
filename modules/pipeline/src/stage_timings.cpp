#include <vlo/pipeline/stage_timings.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace vlo::pipeline
{
std::vector<StageTiming> stageTimings(const kernel::FrameTable& table)
{
	std::vector<StageTiming> out;
	for (const auto& column : table.columns())
	{
		if (column.rfind("ms_", 0) != 0) continue;
		std::vector<double> v;
		for (double ms : table.numbers(column))
			if (std::isfinite(ms)) v.push_back(ms);
		if (v.empty()) continue;
		std::sort(v.begin(), v.end());
		StageTiming t;
		t.stage = column;
		t.count = v.size();
		t.mean = std::accumulate(v.begin(), v.end(), 0.0) / v.size();
		t.p95 = v[static_cast<std::size_t>(std::ceil(0.95 * v.size())) - 1];
		t.max = v.back();
		out.push_back(t);
	}
	return out;
}

std::string formatStageTimings(const std::vector<StageTiming>& timings)
{
	std::size_t width = 5;
	for (const auto& t : timings) width = std::max(width, t.stage.size());
	char line[160];
	std::snprintf(line, sizeof(line), "%-*s %9s %9s %9s %6s", static_cast<int>(width), "stage", "mean ms", "p95 ms",
		"max ms", "frames");
	std::string s = line;
	for (const auto& t : timings)
	{
		std::snprintf(line, sizeof(line), "\n%-*s %9.2f %9.2f %9.2f %6zu", static_cast<int>(width), t.stage.c_str(),
			t.mean, t.p95, t.max, t.count);
		s += line;
	}
	return s;
}
}  // namespace vlo::pipeline
