#pragma once
// Pixel checks shared by the snapshot tests.
#include <vlo/viz/color.h>

#include <opencv2/core.hpp>

#include <cmath>

namespace vlo::test
{
inline double colorDistance(const cv::Vec3b& bgr, Rgb c)
{
	return std::sqrt(std::pow(bgr[0] - c.b, 2) + std::pow(bgr[1] - c.g, 2) + std::pow(bgr[2] - c.r, 2));
}

/// True when a pixel within `radius` of `at` has colour `c` (within `tol` in RGB distance).
inline bool colorNear(const cv::Mat& img, cv::Point2d at, Rgb c, int radius = 2, double tol = 30)
{
	const int x0 = int(std::lround(at.x)), y0 = int(std::lround(at.y));
	for (int y = y0 - radius; y <= y0 + radius; ++y)
		for (int x = x0 - radius; x <= x0 + radius; ++x)
			if (x >= 0 && y >= 0 && x < img.cols && y < img.rows && colorDistance(img.at<cv::Vec3b>(y, x), c) <= tol)
				return true;
	return false;
}
}  // namespace vlo::test
