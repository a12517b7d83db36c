#pragma once
// World -> pixel mapping of a 2D plot, exposed so that callers and tests can place and find things.
#include <opencv2/core/types.hpp>

namespace vlo::viz
{
struct PlotArea
{
	cv::Rect rect;  ///< plot area in image pixels
	double xmin = 0, xmax = 1, ymin = 0, ymax = 1;  ///< world range shown (y grows upwards on screen)

	cv::Point2d toPixel(double x, double y) const
	{
		return {rect.x + (x - xmin) / (xmax - xmin) * rect.width,
			rect.y + rect.height - (y - ymin) / (ymax - ymin) * rect.height};
	}
	double pixelsPerUnitX() const { return rect.width / (xmax - xmin); }
};

/// A round step (1, 2 or 5 times a power of ten) nearest to `approx` (> 0).
double niceStep(double approx);
}  // namespace vlo::viz
