#include "canvas.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vlo::viz::canvas
{
namespace
{
constexpr int kRow = 24, kPad = 10, kSwatch = 34;
}

cv::Size legendSize(const std::vector<LegendItem>& items)
{
	int w = 0;
	for (const auto& it : items) w = std::max(w, textSize(it.label, kMedium).width);
	return {2 * kPad + kSwatch + 10 + w, 2 * kPad + kRow * int(items.size()) - 6};
}

void legend(cv::Mat& img, cv::Point tl, const std::vector<LegendItem>& items)
{
	const cv::Rect box(tl, legendSize(items));
	cv::Mat roi = img(box & cv::Rect(0, 0, img.cols, img.rows));
	roi.convertTo(roi, -1, 0.15, 255 * 0.85);  // mostly opaque: data below stays faintly visible
	cv::rectangle(img, box, cv::Scalar(160, 160, 160), 1);
	for (size_t i = 0; i < items.size(); ++i)
	{
		const auto& it = items[i];
		const int cy = tl.y + kPad + int(i) * kRow + 8, x0 = tl.x + kPad, xm = x0 + kSwatch / 2;
		const cv::Scalar c = bgr(it.color);
		switch (it.kind)
		{
			case LegendItem::Line: cv::line(img, {x0, cy}, {x0 + kSwatch, cy}, c, it.thickness, cv::LINE_AA); break;
			case LegendItem::Dot: cv::circle(img, {xm, cy}, it.thickness, c, cv::FILLED, cv::LINE_AA); break;
			case LegendItem::Square:
				cv::rectangle(img, cv::Rect(xm - 6, cy - 6, 13, 13), c, cv::FILLED);
				cv::rectangle(img, cv::Rect(xm - 6, cy - 6, 13, 13), kInk, 1);
				break;
			case LegendItem::Diamond: diamond(img, {xm, cy}, 8, it.color); break;
			case LegendItem::Ring:
				cv::circle(img, {xm, cy}, 7, kWhite, cv::FILLED, cv::LINE_AA);
				cv::circle(img, {xm, cy}, 7, c, 2, cv::LINE_AA);
				break;
		}
		text(img, it.label, {x0 + kSwatch + 10, cy}, kMedium, kInk, HAlign::Left, VAlign::Middle);
	}
}

void diamond(cv::Mat& img, cv::Point c, int r, Rgb fill)
{
	const std::vector<cv::Point> pts{{c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}};
	cv::fillConvexPoly(img, pts, bgr(fill), cv::LINE_AA);
	cv::polylines(img, pts, true, kInk, 1, cv::LINE_AA);
}

bool startEndMarkers(
	cv::Mat& img, const std::vector<std::pair<std::vector<cv::Point2d>, Rgb>>& paths, std::size_t on_top)
{
	const std::vector<cv::Point2d>* first = nullptr;
	for (const auto& [px, c] : paths)
		if (!px.empty() && !first) first = &px;
	if (!first) return false;
	const cv::Point s = canvas::round(first->front());
	bool late = false;
	const auto endSquare = [&](const std::pair<std::vector<cv::Point2d>, Rgb>& path) {
		if (path.first.empty()) return;
		const cv::Point e = canvas::round(path.first.back());
		const cv::Rect sq(e.x - 6, e.y - 6, 13, 13);
		cv::rectangle(img, sq, canvas::bgr(path.second), cv::FILLED);
		cv::rectangle(img, sq, canvas::kInk, 1);
	};
	for (std::size_t i = paths.size(); i-- > 0;)
		if (i != on_top) endSquare(paths[i]);
	if (on_top < paths.size()) endSquare(paths[on_top]);
	for (const auto& [px, c] : paths)
		if (!px.empty() && cv::norm(px.front() - first->front()) > 4)
		{
			canvas::diamond(img, canvas::round(px.front()), 9, c);
			late = true;
		}
	cv::circle(img, s, 7, canvas::kWhite, cv::FILLED, cv::LINE_AA);
	cv::circle(img, s, 7, canvas::kInk, 2, cv::LINE_AA);
	return late;
}

double colorBarStep(double vmin, double vmax, int width)
{
	// About five ticks, fewer when their labels (as wide as the widest one, plus a gap) would touch.
	for (double step = niceStep((vmax - vmin) / 5);; step = niceStep(step * 2.2))
	{
		const int label = std::max(textSize(formatTick(vmin, step), kSmall).width, textSize(formatTick(vmax, step), kSmall).width);
		if ((vmax - vmin) / step <= 1 || width * step / (vmax - vmin) >= label + 12) return step;
	}
}

void colorBar(cv::Mat& img, const cv::Rect& bar, double vmin, double vmax, const std::string& label,
	const std::function<Rgb(double)>& colormap)
{
	for (int x = 0; x < bar.width; ++x)
	{
		const cv::Scalar c = bgr(colormap((x + 0.5) / bar.width));
		cv::line(img, {bar.x + x, bar.y}, {bar.x + x, bar.y + bar.height - 1}, c, 1);
	}
	cv::rectangle(img, bar, kInk, 1);
	if (!(vmax > vmin)) return;
	const double step = colorBarStep(vmin, vmax, bar.width);
	for (double v = std::ceil(vmin / step) * step; v <= vmax + 1e-9 * step; v += step)
	{
		const int x = bar.x + int(std::lround((v - vmin) / (vmax - vmin) * (bar.width - 1)));
		cv::line(img, {x, bar.y + bar.height}, {x, bar.y + bar.height + 4}, kInk, 1);
		text(img, formatTick(v, step), {x, bar.y + bar.height + 7}, kSmall, kInk, HAlign::Center, VAlign::Top);
	}
	text(img, label, {bar.x + bar.width + 12, bar.y + bar.height / 2}, kMedium, kInk, HAlign::Left, VAlign::Middle);
}
}  // namespace vlo::viz::canvas
