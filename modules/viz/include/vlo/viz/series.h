#pragma once
// Simple line plot of one or more series over a shared x axis (for instance the scale estimate over
// time). Non-finite y values leave gaps.
#include <vlo/viz/color.h>
#include <vlo/viz/plot.h>

#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>
#include <vector>

namespace vlo
{
struct Series
{
	std::string name;
	std::vector<double> x, y;  ///< same length
	std::optional<Rgb> color;  ///< default: paletteColor(index)
	bool markers = false;  ///< a dot at each sample
	bool line = true;  ///< samples joined by a line
	/// Fill the area down to the previous series (to y = 0 for the first) with a light tint of the colour,
	/// for stacked plots; the previous series must have the same x.
	bool fill = false;
};

struct SeriesStyle
{
	int width = 1200, height = 500;
	std::string title, xlabel = "time [s]", ylabel;
	std::optional<double> reference_y;  ///< dashed horizontal line, e.g. 1.0 for a scale factor
	std::optional<double> ymin, ymax;  ///< fixed y range; default: data range plus 5%
};

/// The world -> pixel mapping drawSeries uses. Throws InputError when no series has a finite sample or
/// a series has x and y of different lengths.
PlotArea seriesArea(const std::vector<Series>& series, const SeriesStyle& style = {});
cv::Mat drawSeries(const std::vector<Series>& series, const SeriesStyle& style = {});
void renderSeries(const std::vector<Series>& series, const std::string& png, const SeriesStyle& style = {});
}  // namespace vlo
