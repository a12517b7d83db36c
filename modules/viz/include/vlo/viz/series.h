#pragma once
// Simple line plot of one or more series over a shared x axis (for instance the scale estimate over
// time). Non-finite y values leave gaps.
#include <vlo/viz/color.h>
#include <vlo/viz/plot.h>

#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>
#include <vector>

namespace vlo::viz
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
	int marker_radius = 3;  ///< in pixels; a larger dot gets an ink outline so that it stands out of smaller ones
};

struct SeriesStyle
{
	int width = 1200, height = 500;
	std::string title, xlabel = "time [s]", ylabel;
	std::optional<double> reference_y;  ///< dashed horizontal line, e.g. 1.0 for a scale factor
	std::optional<double> ymin, ymax;  ///< fixed y range; default: data range plus 5%
	std::optional<double> xmin, xmax;  ///< fixed x range; default: data range
	bool legend_outside = false;  ///< legend right of the plot area (which narrows), not in its emptiest corner
};

/// One panel of a figure of panels stacked top to bottom over a shared x axis.
struct SeriesPanel
{
	std::vector<Series> series;
	SeriesStyle style;  ///< its height is the panel's; width, xmin and xmax are the figure's
};

/// The world -> pixel mapping drawSeries uses. Throws InputError when no series has a finite sample or
/// a series has x and y of different lengths.
PlotArea seriesArea(const std::vector<Series>& series, const SeriesStyle& style = {});
cv::Mat drawSeries(const std::vector<Series>& series, const SeriesStyle& style = {});
void renderSeries(const std::vector<Series>& series, const std::string& png, const SeriesStyle& style = {});

/// Panels over the same x range (the union of theirs, unless the first panel's style fixes it), each with its own y
/// axis and legend, the first panel's width for all. Panel k's mapping is seriesArea(panels[k].series, its style with
/// that x range and width), moved down by the heights of the panels above. Throws InputError as seriesArea does, or
/// for no panel.
std::vector<PlotArea> seriesPanelAreas(const std::vector<SeriesPanel>& panels);
cv::Mat drawSeriesPanels(const std::vector<SeriesPanel>& panels);
void renderSeriesPanels(const std::vector<SeriesPanel>& panels, const std::string& png);
}  // namespace vlo::viz
