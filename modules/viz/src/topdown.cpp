#include <vlo/core/error.h>
#include <vlo/viz/png.h>
#include <vlo/viz/topdown.h>

#include "canvas.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vlo::viz
{
namespace
{
constexpr int kLeft = 95, kRight = 30, kBottom = 80;
int topMargin(const TopDownStyle& s) { return s.title.empty() ? 30 : 60; }

std::vector<cv::Point2d> pixels(const Trajectory& t, const PlotArea& a)
{
	std::vector<cv::Point2d> px;
	px.reserve(t.size());
	for (const auto& p : t) px.push_back(a.toPixel(p.pose.translation().x(), p.pose.translation().y()));
	return px;
}

/// A length `v` in `unit` with the printf `format` for its number; metres from `km_from` on in km (an unscaled
/// VO's map units never become km).
std::string lengthText(double v, const std::string& unit, double km_from, const char* format)
{
	char buf[48];
	const bool km = unit == "m" && v >= km_from;
	std::snprintf(buf, sizeof buf, format, km ? v / 1000 : v);
	return std::string(buf) + (km ? " km" : " " + unit);
}

/// A path's length: one decimal below 100, so that short paths that differ by a few percent show it.
std::string pathLengthText(double v, const std::string& unit)
{
	const bool km = unit == "m" && v >= 10000;
	return lengthText(v, unit, 10000, km || v < 100 ? "%.1f" : "%.0f");
}

/// The largest of the values that colour the first path (checked against its pose count); -1 when none.
double largestValue(const std::vector<NamedTrajectory>& trajs, const std::vector<double>& values)
{
	if (values.empty()) return -1;
	if (trajs.empty() || values.size() != trajs[0].traj.size())
		failInput("top-down view",
			std::to_string(values.size()) + " values for " +
				std::to_string(trajs.empty() ? 0 : trajs[0].traj.size()) + " poses of the first trajectory");
	double vmax = 0;
	for (const double v : values)
		if (std::isfinite(v)) vmax = std::max(vmax, v);
	return vmax;
}

Rgb valueColor(double v, double vmax) { return turbo(vmax > 0 ? v / vmax : 0); }

/// Round-length bar in metres, boxed, at `tl`.
void scaleBar(cv::Mat& img, cv::Point tl, cv::Size box, int barPx, const std::string& label)
{
	cv::Mat roi = img(cv::Rect(tl, box));
	roi.convertTo(roi, -1, 0.15, 255 * 0.85);
	const int x0 = tl.x + (box.width - barPx) / 2, y = tl.y + box.height - 14;
	cv::rectangle(img, cv::Rect(x0, y - 4, barPx, 6), canvas::kInk, cv::FILLED);
	cv::line(img, {x0, y - 10}, {x0, y + 2}, canvas::kInk, 2);
	cv::line(img, {x0 + barPx - 1, y - 10}, {x0 + barPx - 1, y + 2}, canvas::kInk, 2);
	canvas::text(img, label, {tl.x + box.width / 2, y - 14}, canvas::kMedium, canvas::kInk, canvas::HAlign::Center);
}
}  // namespace

PlotArea topDownArea(const std::vector<NamedTrajectory>& trajs, const Trajectory* gt, const TopDownStyle& style)
{
	double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
	auto grow = [&](const Trajectory& t) {
		for (const auto& p : t)
		{
			const auto& v = p.pose.translation();
			x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x()), y0 = std::min(y0, v.y()), y1 = std::max(y1, v.y());
		}
	};
	for (const auto& t : trajs) grow(t.traj);
	if (gt) grow(*gt);
	if (!(x1 >= x0)) failInput("top-down view", "no poses to draw (all trajectories are empty)");

	PlotArea a;
	const int top = topMargin(style);
	a.rect = cv::Rect(kLeft, top, style.width - kLeft - kRight, style.height - top - kBottom);
	if (a.rect.width < 100 || a.rect.height < 100) failInput("top-down view", "image size too small");
	// Equal aspect: fit the larger relative extent (plus 5% padding), widen the other to fill.
	const double span = std::max({x1 - x0, y1 - y0, 1.0}) * 1.10;
	const double ppm = std::min(a.rect.width / std::max(x1 - x0 + 0.1 * span, 1.0),
		a.rect.height / std::max(y1 - y0 + 0.1 * span, 1.0));
	const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
	a.xmin = cx - 0.5 * a.rect.width / ppm, a.xmax = cx + 0.5 * a.rect.width / ppm;
	a.ymin = cy - 0.5 * a.rect.height / ppm, a.ymax = cy + 0.5 * a.rect.height / ppm;
	return a;
}

cv::Mat drawTopDown(const std::vector<NamedTrajectory>& trajs, const Trajectory* gt, const TopDownStyle& style)
{
	const PlotArea a = topDownArea(trajs, gt, style);
	cv::Mat img(style.height, style.width, CV_8UC3, canvas::kWhite);
	const double step = niceStep((a.xmax - a.xmin) / std::max(2.0, a.rect.width / 130.0));
	canvas::axes(img, a, step, step, "x [" + style.unit + "]  (forward at the first frame)",
		"y [" + style.unit + "]  (left at the first frame)");
	if (!style.title.empty())
		canvas::text(img, style.title, {style.width / 2, 18}, canvas::kLarge, canvas::kInk, canvas::HAlign::Center,
			canvas::VAlign::Top, 2);

	std::vector<canvas::LegendItem> items;
	std::vector<cv::Point2d> all;  // every drawn pixel position, to keep boxes off the data
	cv::Mat plot = img(a.rect);  // clip lines to the plot area
	const cv::Point2d off(-a.rect.x, -a.rect.y);
	const double vmax = largestValue(trajs, style.values);
	auto draw = [&](const Trajectory& t, Rgb c, int width, const std::vector<double>& values = {}) {
		auto px = pixels(t, a);
		all.insert(all.end(), px.begin(), px.end());
		for (auto& p : px) p += off;
		if (values.empty() && !px.empty()) canvas::polyline(plot, px, canvas::bgr(c), width);
		for (size_t i = 1; i < px.size() && !values.empty(); ++i)
			canvas::polyline(plot, {px[i - 1], px[i]}, canvas::bgr(valueColor(0.5 * (values[i - 1] + values[i]), vmax)),
				width + 1);
		return px;
	};
	auto label = [&](const std::string& name, const Trajectory& t) {
		if (t.empty()) return name + "  (empty)";
		return style.show_lengths ? name + "  (" + pathLengthText(pathLength(t), style.unit) + ")" : name;
	};
	std::vector<std::pair<std::vector<cv::Point2d>, Rgb>> markers;
	if (gt)
	{
		markers.push_back({draw(*gt, kGroundTruthColor, style.line_width + 3), kGroundTruthColor});
		items.push_back({canvas::LegendItem::Line, label(style.gt_name, *gt), kGroundTruthColor, style.line_width + 3});
	}
	// The first trajectory is the main result: drawn last, above the others; the legend keeps the list order.
	std::vector<std::pair<std::vector<cv::Point2d>, Rgb>> paths(trajs.size());
	for (size_t i = trajs.size(); i-- > 0;)
	{
		const std::vector<double> none, &values = i == 0 ? style.values : none;
		const Rgb c = values.empty() ? trajs[i].color.value_or(paletteColor(i)) : valueColor(0.5 * vmax, vmax);
		paths[i] = {draw(trajs[i].traj, c, style.line_width, values), c};
	}
	for (size_t i = 0; i < trajs.size(); ++i)
	{
		const std::string name = i > 0 || style.values.empty() ? trajs[i].name
															   : trajs[i].name + ", coloured by " + style.value_label;
		items.push_back({canvas::LegendItem::Line, label(name, trajs[i].traj), paths[i].second, style.line_width + 1});
	}
	if (!style.links.empty())
	{
		for (const auto& [from, to] : style.links)
			canvas::polyline(plot, {a.toPixel(from.x(), from.y()) + off, a.toPixel(to.x(), to.y()) + off}, canvas::bgr(style.links_color), 2);
		items.push_back({canvas::LegendItem::Line, style.links_label + " (" + std::to_string(style.links.size()) + ")", style.links_color, 2});
	}
	markers.insert(markers.end(), paths.begin(), paths.end());
	const bool late = canvas::startEndMarkers(plot, markers, gt ? 1 : 0);  // the main result's end above the others
	items.push_back({canvas::LegendItem::Ring, "start of the drive", Rgb{40, 40, 40}});
	if (late) items.push_back({canvas::LegendItem::Diamond, "start of a path that began later", Rgb{200, 200, 200}});
	items.push_back({canvas::LegendItem::Square, "end", Rgb{200, 200, 200}});

	const cv::Size lsz = canvas::legendSize(items);
	const cv::Point ltl = canvas::emptiestCorner(a.rect, lsz, all);
	canvas::legend(img, ltl, items);

	if (vmax >= 0)
	{
		// The axes already give the metres; the colour bar is what a coloured path needs.
		const int barW = 260, labelW = canvas::textSize(style.value_label, canvas::kMedium).width;
		const cv::Size csz(barW + labelW + 44, 58);
		const cv::Point tl = canvas::emptiestCorner(a.rect, csz, all, cv::Rect(ltl, lsz));
		cv::Mat roi = img(cv::Rect(tl, csz));
		roi.convertTo(roi, -1, 0.15, 255 * 0.85);
		canvas::colorBar(img, cv::Rect(tl.x + 14, tl.y + 10, barW, 16), 0, vmax, style.value_label,
			[&](double t) { return valueColor(t * vmax, vmax); });
		return img;
	}
	const double barM = niceStep((a.xmax - a.xmin) * 0.18);
	const int barPx = int(std::lround(barM * a.pixelsPerUnitX()));
	const cv::Size bsz(barPx + 40, 52);
	scaleBar(img, canvas::emptiestCorner(a.rect, bsz, all, cv::Rect(ltl, lsz)), bsz, barPx, lengthText(barM, style.unit, 1000, "%g"));
	return img;
}

void renderTopDown(const std::vector<NamedTrajectory>& trajs, const Trajectory* gt, const std::string& png,
	const TopDownStyle& style)
{
	writePng(png, drawTopDown(trajs, gt, style));
}
}  // namespace vlo::viz
