#pragma once
// Internal: the only place that touches mrpt::opengl, so its heavy headers stay out of the others.
#include <vlo/viz/color.h>

#include "view_fit.h"

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include <vector>

namespace vlo::viz
{
struct GlPoint
{
	Eigen::Vector3f p;
	Rgb c;
};
using GlPoints = std::vector<GlPoint>;

/// Renders coloured points on white through `cam` (headless EGL). Returns a BGR image of cam's size.
cv::Mat renderPoints(const GlPoints& pts, const ViewCamera& cam, float pointSize);
}  // namespace vlo::viz
