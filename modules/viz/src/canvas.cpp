#include "canvas.h"
#include "hershey_text.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vlo::viz
{
double niceStep(double approx)
{
	if (!(approx > 0) || !std::isfinite(approx)) return 1.0;
	const double p = std::pow(10.0, std::floor(std::log10(approx)));
	const double m = approx / p;  // in [1, 10)
	return p * (m < 1.5 ? 1 : m < 3.5 ? 2
					   : m < 7.5      ? 5
									  : 10);
}
}  // namespace vlo::viz

namespace vlo::viz::canvas
{
namespace
{
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
}

cv::Size textSize(const std::string& text, double scale, int thickness)
{
	int baseline = 0;
	return cv::getTextSize(hersheyText(text), kFont, scale, thickness, &baseline);
}

void text(cv::Mat& img, const std::string& s, cv::Point at, double scale, cv::Scalar color, HAlign h, VAlign v,
	int thickness)
{
	const cv::Size sz = textSize(s, scale, thickness);
	const int x = h == HAlign::Left ? at.x : h == HAlign::Center ? at.x - sz.width / 2
																 : at.x - sz.width;
	const int y = v == VAlign::Bottom ? at.y : v == VAlign::Middle ? at.y + sz.height / 2
																   : at.y + sz.height;
	cv::putText(img, hersheyText(s), {x, y}, kFont, scale, color, thickness, cv::LINE_AA);
}

void textVertical(cv::Mat& img, const std::string& s, cv::Point center, double scale, cv::Scalar color)
{
	const cv::Size sz = textSize(s, scale);
	const int w = sz.width + 4, h = sz.height + 8;  // upright text box; on screen it is h wide, w tall
	const cv::Rect roi = cv::Rect(center.x - h / 2, center.y - w / 2, h, w) & cv::Rect(0, 0, img.cols, img.rows);
	if (roi.width != h || roi.height != w) return;  // does not fit: skip rather than clip letters
	// Rotate the background upright, write, rotate back, so that the text blends with what is there.
	cv::Mat upright;
	cv::rotate(img(roi), upright, cv::ROTATE_90_CLOCKWISE);
	text(upright, s, {2, h - 5}, scale, color);
	cv::Mat back;
	cv::rotate(upright, back, cv::ROTATE_90_COUNTERCLOCKWISE);
	back.copyTo(img(roi));
}

cv::Point round(const cv::Point2d& p) { return {int(std::lround(p.x)), int(std::lround(p.y))}; }

void polyline(cv::Mat& img, const std::vector<cv::Point2d>& pts, cv::Scalar color, int thickness)
{
	constexpr int kShift = 4;  // 1/16 pixel precision keeps thin curves smooth
	std::vector<cv::Point> fixed;
	fixed.reserve(pts.size());
	for (const auto& p : pts)
	{
		const cv::Point q(int(std::lround(p.x * (1 << kShift))), int(std::lround(p.y * (1 << kShift))));
		if (fixed.empty() || q != fixed.back()) fixed.push_back(q);
	}
	if (fixed.size() == 1) fixed.push_back(fixed.back());  // a single point still shows as a dot
	cv::polylines(img, fixed, false, color, thickness, cv::LINE_AA, kShift);
}

std::string formatTick(double v, double step)
{
	const int decimals = std::max(0, int(std::ceil(-std::log10(step) - 1e-9)));
	if (std::abs(v) < step * 1e-6) v = 0;  // no "-0"
	char buf[64];
	std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
	return buf;
}

void axes(cv::Mat& img, const PlotArea& a, double xstep, double ystep, const std::string& xlabel,
	const std::string& ylabel)
{
	const cv::Rect& r = a.rect;
	int maxLabelW = 0;
	for (double x = std::ceil(a.xmin / xstep) * xstep; x <= a.xmax + 1e-9 * xstep; x += xstep)
	{
		const int px = int(std::lround(a.toPixel(x, 0).x));
		cv::line(img, {px, r.y}, {px, r.y + r.height}, kGrid, 1);
		cv::line(img, {px, r.y + r.height}, {px, r.y + r.height + 5}, kInk, 1);
		text(img, formatTick(x, xstep), {px, r.y + r.height + 9}, kSmall, kInk, HAlign::Center, VAlign::Top);
	}
	for (double y = std::ceil(a.ymin / ystep) * ystep; y <= a.ymax + 1e-9 * ystep; y += ystep)
	{
		const int py = int(std::lround(a.toPixel(0, y).y));
		cv::line(img, {r.x, py}, {r.x + r.width, py}, kGrid, 1);
		cv::line(img, {r.x - 5, py}, {r.x, py}, kInk, 1);
		const std::string s = formatTick(y, ystep);
		maxLabelW = std::max(maxLabelW, textSize(s, kSmall).width);
		text(img, s, {r.x - 9, py}, kSmall, kInk, HAlign::Right, VAlign::Middle);
	}
	cv::rectangle(img, r, kInk, 1);
	text(img, xlabel, {r.x + r.width / 2, r.y + r.height + 34}, kMedium, kInk, HAlign::Center, VAlign::Top);
	textVertical(img, ylabel, {r.x - maxLabelW - 26, r.y + r.height / 2}, kMedium);
}

cv::Point emptiestCorner(const cv::Rect& area, cv::Size size, const std::vector<cv::Point2d>& pts,
	const cv::Rect& taken, int pad)
{
	const int l = area.x + pad, t = area.y + pad;
	const int rr = area.x + area.width - pad - size.width, b = area.y + area.height - pad - size.height;
	const cv::Point corners[] = {{l, t}, {rr, t}, {rr, b}, {l, b}};
	cv::Point best = corners[0];
	long bestCount = -1;
	for (const auto& c : corners)
	{
		const cv::Rect box(c, size);
		if ((box & taken).area() > 0) continue;
		const cv::Rect grown(box.x - 6, box.y - 6, box.width + 12, box.height + 12);
		long n = 0;
		for (const auto& p : pts) n += grown.contains(round(p));
		if (bestCount < 0 || n < bestCount)
		{
			bestCount = n;
			best = c;
		}
	}
	return best;
}
}  // namespace vlo::viz::canvas
