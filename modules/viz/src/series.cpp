#include <vlo/core/error.h>
#include <vlo/viz/png.h>
#include <vlo/viz/series.h>

#include "canvas.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vlo::viz
{
namespace
{
constexpr int kLeft = 95, kRight = 30, kBottom = 80;
int topMargin(const SeriesStyle& s) { return s.title.empty() ? 30 : 60; }

void dashedLine(cv::Mat& img, cv::Point a, cv::Point b, cv::Scalar c)
{
	const double len = std::hypot(b.x - a.x, b.y - a.y);
	for (double s = 0; s < len; s += 16)
	{
		const double e = std::min(len, s + 9);
		cv::line(img, a + (b - a) * (s / len), a + (b - a) * (e / len), c, 1, cv::LINE_AA);
	}
}
cv::Scalar tint(Rgb c) { return canvas::bgr({std::uint8_t(c.r / 2 + 128), std::uint8_t(c.g / 2 + 128), std::uint8_t(c.b / 2 + 128)}); }

std::vector<canvas::LegendItem> legendItems(const std::vector<Series>& series)
{
	std::vector<canvas::LegendItem> items;
	if (series.size() == 1 && series[0].name.empty()) return items;  // nothing to tell apart
	for (size_t k = 0; k < series.size(); ++k)
	{
		const auto& s = series[k];
		items.push_back({s.line ? canvas::LegendItem::Line : canvas::LegendItem::Dot, s.name,
			s.color.value_or(paletteColor(k)), s.line ? 2 : s.marker_radius + 1});
	}
	return items;
}

/// Fills between series k and k - 1 (or y = 0), sample by sample; non-finite samples leave gaps.
void fillBelow(cv::Mat& plot, const PlotArea& a, const std::vector<Series>& series, size_t k, cv::Point2d off)
{
	const Series& s = series[k];
	if (k > 0 && series[k - 1].x != s.x)
		failInput("series plot", "'" + s.name + "' is filled down to '" + series[k - 1].name + "', which has other x values");
	const Rgb c = s.color.value_or(paletteColor(k));
	for (size_t i = 1; i < s.x.size(); ++i)
	{
		const double b0 = k > 0 ? series[k - 1].y[i - 1] : 0.0, b1 = k > 0 ? series[k - 1].y[i] : 0.0;
		const double v[] = {s.x[i - 1], s.x[i], s.y[i - 1], s.y[i], b0, b1};
		if (!std::all_of(std::begin(v), std::end(v), [](double d) { return std::isfinite(d); })) continue;
		const std::vector<cv::Point> quad{canvas::round(a.toPixel(s.x[i - 1], s.y[i - 1]) + off),
			canvas::round(a.toPixel(s.x[i], s.y[i]) + off), canvas::round(a.toPixel(s.x[i], b1) + off),
			canvas::round(a.toPixel(s.x[i - 1], b0) + off)};
		cv::fillConvexPoly(plot, quad, tint(c));
	}
}
}  // namespace

PlotArea seriesArea(const std::vector<Series>& series, const SeriesStyle& style)
{
	double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
	for (const auto& s : series)
	{
		if (s.x.size() != s.y.size())
			failInput("series plot",
				"series '" + s.name + "' has " + std::to_string(s.x.size()) + " x values but " +
					std::to_string(s.y.size()) + " y values");
		for (size_t i = 0; i < s.x.size(); ++i)
			if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
			{
				x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
				y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
			}
	}
	if (!(x1 >= x0)) failInput("series plot", "nothing to plot (no finite sample)");
	if (style.reference_y) y0 = std::min(y0, *style.reference_y), y1 = std::max(y1, *style.reference_y);
	if (x1 - x0 < 1e-9) x0 -= 0.5, x1 += 0.5;
	const double ypad = std::max(0.05 * (y1 - y0), 1e-6 * std::max(1.0, std::abs(y0)));
	PlotArea a;
	const int top = topMargin(style);
	const int legendWidth = style.legend_outside ? canvas::legendSize(legendItems(series)).width + 20 : 0;
	a.rect = cv::Rect(kLeft, top, style.width - kLeft - kRight - legendWidth, style.height - top - kBottom);
	if (a.rect.width < 100 || a.rect.height < 60) failInput("series plot", "image size too small");
	a.xmin = style.xmin.value_or(x0), a.xmax = style.xmax.value_or(x1);
	if (!(a.xmax > a.xmin)) failInput("series plot", "empty x range");
	a.ymin = style.ymin.value_or(y0 - ypad), a.ymax = style.ymax.value_or(y1 + ypad);
	if (!(a.ymax > a.ymin)) failInput("series plot", "empty y range");
	return a;
}

cv::Mat drawSeries(const std::vector<Series>& series, const SeriesStyle& style)
{
	const PlotArea a = seriesArea(series, style);
	cv::Mat img(style.height, style.width, CV_8UC3, canvas::kWhite);
	const double xstep = niceStep((a.xmax - a.xmin) / std::max(2.0, a.rect.width / 110.0));
	const double ystep = niceStep((a.ymax - a.ymin) / std::max(2.0, a.rect.height / 60.0));
	canvas::axes(img, a, xstep, ystep, style.xlabel, style.ylabel);
	if (!style.title.empty())
		canvas::text(img, style.title, {style.width / 2, 18}, canvas::kLarge, canvas::kInk, canvas::HAlign::Center,
			canvas::VAlign::Top, 2);
	cv::Mat plot = img(a.rect);
	const cv::Point2d off(-a.rect.x, -a.rect.y);
	for (size_t k = 0; k < series.size(); ++k)
		if (series[k].fill) fillBelow(plot, a, series, k, off);
	if (style.reference_y)  // above the fills (a budget line must show through a stack), below the data
	{
		const int y = int(std::lround(a.toPixel(0, *style.reference_y).y + off.y));
		dashedLine(plot, {0, y}, {a.rect.width, y}, canvas::kInk);
	}
	std::vector<cv::Point2d> all;
	for (size_t k = 0; k < series.size(); ++k)
	{
		const auto& s = series[k];
		const cv::Scalar c = canvas::bgr(s.color.value_or(paletteColor(k)));
		std::vector<cv::Point2d> run;  // consecutive finite samples
		auto flush = [&] {
			if (!run.empty() && s.line) canvas::polyline(plot, run, c, 2);
			run.clear();
		};
		for (size_t i = 0; i < s.x.size(); ++i)
		{
			if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]))
			{
				flush();
				continue;
			}
			const cv::Point2d p = a.toPixel(s.x[i], s.y[i]);
			all.push_back(p);
			run.push_back(p + off);
			if (!s.markers) continue;
			cv::circle(plot, canvas::round(p + off), s.marker_radius, c, cv::FILLED, cv::LINE_AA);
			if (s.marker_radius > 3) cv::circle(plot, canvas::round(p + off), s.marker_radius, canvas::kInk, 1, cv::LINE_AA);
		}
		flush();
	}
	const std::vector<canvas::LegendItem> items = legendItems(series);
	if (items.empty()) return img;
	const cv::Point at = style.legend_outside ? cv::Point(a.rect.br().x + 20, a.rect.y)
											  : canvas::emptiestCorner(a.rect, canvas::legendSize(items), all);
	canvas::legend(img, at, items);
	return img;
}

void renderSeries(const std::vector<Series>& series, const std::string& png, const SeriesStyle& style)
{
	writePng(png, drawSeries(series, style));
}

namespace
{
/// Each panel's style with the figure's width and shared x range.
std::vector<SeriesStyle> panelStyles(const std::vector<SeriesPanel>& panels)
{
	if (panels.empty()) failInput("series plot", "no panel to draw");
	double x0 = INFINITY, x1 = -INFINITY;
	for (const auto& p : panels)
	{
		const PlotArea a = seriesArea(p.series, p.style);
		x0 = std::min(x0, a.xmin), x1 = std::max(x1, a.xmax);
	}
	std::vector<SeriesStyle> styles;
	for (const auto& p : panels)
	{
		styles.push_back(p.style);
		styles.back().width = panels.front().style.width;
		styles.back().xmin = panels.front().style.xmin.value_or(x0);
		styles.back().xmax = panels.front().style.xmax.value_or(x1);
	}
	return styles;
}
}  // namespace

std::vector<PlotArea> seriesPanelAreas(const std::vector<SeriesPanel>& panels)
{
	const std::vector<SeriesStyle> styles = panelStyles(panels);
	std::vector<PlotArea> areas;
	int top = 0;
	for (std::size_t k = 0; k < panels.size(); ++k)
	{
		areas.push_back(seriesArea(panels[k].series, styles[k]));
		areas.back().rect.y += top;
		top += styles[k].height;
	}
	return areas;
}

cv::Mat drawSeriesPanels(const std::vector<SeriesPanel>& panels)
{
	const std::vector<SeriesStyle> styles = panelStyles(panels);
	std::vector<cv::Mat> drawn;
	for (std::size_t k = 0; k < panels.size(); ++k) drawn.push_back(drawSeries(panels[k].series, styles[k]));
	cv::Mat img;
	cv::vconcat(drawn, img);
	return img;
}

void renderSeriesPanels(const std::vector<SeriesPanel>& panels, const std::string& png)
{
	writePng(png, drawSeriesPanels(panels));
}
}  // namespace vlo::viz
