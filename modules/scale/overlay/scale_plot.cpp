#include <vlo/scale/scale_plot.h>

#include <algorithm>
#include <cmath>

namespace vlo::scale
{
namespace
{
// Okabe-Ito: a cloud of blue estimates, the cumulative factor as a bluish-green step line, vermillion correction
// markers on top; the inliers in their own panel in reddish purple. Rejected estimates in neutral grey, underneath.
constexpr viz::Rgb kRejected{170, 170, 170}, kEstimate{0, 114, 178}, kCorrection{213, 94, 0}, kCumulative{0, 158, 115}, kInliers{204, 121, 167};

bool anyFinite(const std::vector<double>& v)
{
	return std::any_of(v.begin(), v.end(), [](double y) { return std::isfinite(y); });
}

/// Steps: the value holds until the next sample changes it (a factor applies from its frame on).
viz::Series steps(const std::string& name, const std::vector<double>& x, const std::vector<double>& y, viz::Rgb c)
{
	viz::Series s{name, {}, {}, c, false, true};
	for (std::size_t i = 0; i < x.size(); ++i)
	{
		if (i > 0 && std::isfinite(y[i - 1]) && std::isfinite(y[i]) && y[i] != y[i - 1])
			s.x.push_back(x[i]), s.y.push_back(y[i - 1]);
		s.x.push_back(x[i]), s.y.push_back(y[i]);
	}
	return s;
}
}  // namespace

void ScaleHistory::add(
	std::size_t frame_index, double estimate_or_nan, int inlier_count, double applied, double cum, double rejected_or_nan)
{
	frame.push_back(double(frame_index));
	estimate.push_back(estimate_or_nan);
	rejected.push_back(rejected_or_nan);
	inliers.push_back(inlier_count);
	correction.push_back(applied != 1.0 ? applied : std::nan(""));
	cumulative.push_back(cum > 0 ? cum : std::nan(""));
}

std::vector<viz::SeriesPanel> scalePlotPanels(const ScaleHistory& h)
{
	viz::SeriesPanel top, bottom;
	viz::Series estimate{"estimate s = LiDAR depth / visual depth", h.frame, h.estimate, kEstimate, true, false};
	viz::Series correction{"correction applied to the VO map", h.frame, h.correction, kCorrection, true, false};
	correction.marker_radius = 6;
	viz::Series rejected{"rejected estimate (not valid: see frames.csv)", h.frame, h.rejected, kRejected, true, false};
	// Only what appears, so that the legend names no category the reader then looks for in vain.
	for (auto& s : {rejected, estimate, steps("cumulative correction (product so far)", h.frame, h.cumulative, kCumulative),
			 correction})
		if (anyFinite(s.y)) top.series.push_back(s);
	top.style.height = 460;
	top.style.title = "Scale of the metric VO map per frame (dashed: 1, no drift)";
	top.style.xlabel = "";
	top.style.ylabel = "scale factor [-]";
	top.style.reference_y = 1.0;
	// Room above the data for the legend, which the scatter of estimates fills otherwise.
	double lo = 1.0, hi = 1.0;
	// Rejected estimates can be far off: they do not stretch the axis (those out of range are off the plot).
	for (const auto* v : {&h.estimate, &h.correction, &h.cumulative})
		for (double y : *v)
			if (std::isfinite(y)) lo = std::min(lo, y), hi = std::max(hi, y);
	const double pad = std::max(0.01, 0.05 * (hi - lo));
	top.style.ymin = lo - pad, top.style.ymax = hi + pad + 0.45 * (hi - lo + 2 * pad);
	bottom.series = {{"RANSAC inliers of the estimate", h.frame, h.inliers, kInliers, true, false}};
	bottom.style.height = 300;
	bottom.style.xlabel = "frame";
	bottom.style.ylabel = "inliers [points]";

	double most = 1;
	for (double n : h.inliers)
		if (std::isfinite(n)) most = std::max(most, n);
	bottom.style.ymin = -0.04 * most;  // a zero count above the axis line, not hidden by it
	bottom.style.ymax = 1.35 * most;  // the legend above the dots
	return {top, bottom};
}

bool renderScalePlot(const ScaleHistory& h, const std::string& png)
{
	if (!anyFinite(h.estimate) && !anyFinite(h.rejected) && !anyFinite(h.correction)) return false;
	viz::renderSeriesPanels(scalePlotPanels(h), png);
	return true;
}
}  // namespace vlo::scale
