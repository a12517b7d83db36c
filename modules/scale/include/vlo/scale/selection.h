#pragma once
// Keypoints among the projected LiDAR pixels: the corner test (FAST-9 or the FAST-12 pre-test), the
// gradient threshold, then a grid non-maximum suppression for a uniform spread, then a cap.
#include <vlo/scale/options.h>
#include <vlo/scale/projection.h>

#include <opencv2/core/mat.hpp>

#include <Eigen/Core>

#include <vector>

namespace vlo::scale
{
struct Keypoint
{
	int projected = -1;  ///< index into the projected pixels
	float score = 0;  ///< gradient magnitude [grey levels / px]: the NMS ranks by it
};

struct SelectionCounts
{
	int corner = 0;  ///< passed the corner test
	int gradient = 0;  ///< ... and the gradient threshold
	int direction = 0;  ///< ... and the gradient direction pre-test (before NMS)
};

/// One keypoint per nms_cell x nms_cell cell (the strongest gradient; ties: the lower scan index),
/// at most max_keypoints, strongest first. `img` is C(i-1), 8-bit grey.
/// `epipole`: the epipole in C(i-1) (homogeneous, K times the centre of C(i)); with it and
/// preselect_min_abs_cos > 0, eq. 4 is applied early in C(i-1): every epipolar line of C(i-1) passes
/// through the epipole, so the line direction at a pixel is known before tracking. Keypoints whose
/// gradient runs along their line would be culled after tracking anyway; dropping them here lets
/// the NMS keep a better neighbour and saves their LK cost.
std::vector<Keypoint> selectKeypoints(const cv::Mat& img, const std::vector<DepthPixel>& projected,
	const ScaleOptions& opt, SelectionCounts* counts = nullptr, const Eigen::Vector3d* epipole = nullptr);

/// The corner test chosen by opt.keypoint_test at a pixel (at least 3 px inside the image).
bool cornerTest(const cv::Mat& img, int x, int y, const ScaleOptions& opt);
}  // namespace vlo::scale
