#pragma once
// Pixel checks shared by the snapshot tests.
#include <vlo/viz/color.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vlo::test
{
inline double colorDistance(const cv::Vec3b& bgr, viz::Rgb c)
{
	return std::sqrt(std::pow(bgr[0] - c.b, 2) + std::pow(bgr[1] - c.g, 2) + std::pow(bgr[2] - c.r, 2));
}

/// True when a pixel within `radius` of `at` has colour `c` (within `tol` in RGB distance).
inline bool colorNear(const cv::Mat& img, cv::Point2d at, viz::Rgb c, int radius = 2, double tol = 30)
{
	const int x0 = int(std::lround(at.x)), y0 = int(std::lround(at.y));
	for (int y = y0 - radius; y <= y0 + radius; ++y)
		for (int x = x0 - radius; x <= x0 + radius; ++x)
			if (x >= 0 && y >= 0 && x < img.cols && y < img.rows && colorDistance(img.at<cv::Vec3b>(y, x), c) <= tol)
				return true;
	return false;
}

/// Distance in pixels from `p` to the polyline through `pts`.
inline double distanceToPolyline(cv::Point2d p, const std::vector<cv::Point2d>& pts)
{
	double best = pts.empty() ? INFINITY : cv::norm(p - pts.front());
	for (size_t i = 1; i < pts.size(); ++i)
	{
		const cv::Point2d d = pts[i] - pts[i - 1];
		const double len2 = d.dot(d);
		const double t = len2 > 0 ? std::clamp((p - pts[i - 1]).dot(d) / len2, 0.0, 1.0) : 0.0;
		best = std::min(best, cv::norm(p - (pts[i - 1] + t * d)));
	}
	return best;
}

/// The box of a legend drawn by canvas::legend, found by its 1-pixel border of exactly (160, 160, 160): the
/// top-most row with a run of at least 40 border pixels, down its left edge. Empty when there is none.
inline cv::Rect findLegend(const cv::Mat& img)
{
	const cv::Vec3b border(160, 160, 160);
	for (int y = 0; y < img.rows; ++y)
		for (int x = 0, run = 0; x < img.cols; ++x)
		{
			run = img.at<cv::Vec3b>(y, x) == border ? run + 1 : 0;
			if (run < 40) continue;
			int x0 = x - run + 1, x1 = x;
			while (x1 + 1 < img.cols && img.at<cv::Vec3b>(y, x1 + 1) == border) ++x1;
			int y1 = y;
			while (y1 + 1 < img.rows && img.at<cv::Vec3b>(y1 + 1, x0) == border) ++y1;
			return {x0, y, x1 - x0 + 1, y1 - y + 1};
		}
	return {};
}

/// Centre of the colour swatch of row `i` of a legend box (canvas::legend: 10 px padding, 24 px rows, 34 px swatches).
inline cv::Point2d legendSwatch(const cv::Rect& box, int i) { return {box.x + 27.0, box.y + 18.0 + 24 * i}; }
}  // namespace vlo::test
