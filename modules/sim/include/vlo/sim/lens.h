#pragma once
// A lens as remap tables: where each pixel of a distorted camera looks in the pinhole image with the
// same intrinsics. Rendering through a lens (CameraSim) and distorting real pinhole images (the
// e2e tests' KITTI snippet) both sample a pinhole picture there.
#include <vlo/core/frame.h>

#include <opencv2/core.hpp>

namespace vlo::sim
{
struct LensMaps
{
	cv::Mat x, y;  ///< CV_32F, the distorted camera's size: pinhole pixel coordinates (OpenCV convention)
};

/// For the distorted camera `K` (plumb_bob or kannala_brandt): each pixel's ray as a pixel of the
/// pinhole camera with K's fx, fy, cx, cy (non-finite where the ray does not project).
LensMaps pinholeLookup(const PinholeCamera& K);

/// The pinhole image `pinhole` (K's intrinsics, any size and type) as the lens of `maps` sees it; rays
/// beyond the picture see black.
cv::Mat throughLens(const cv::Mat& pinhole, const LensMaps& maps);
}  // namespace vlo::sim
