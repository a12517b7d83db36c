#pragma once
// Pyramidal Lucas-Kanade tracking of the keypoints from C(i-1) into C(i), with an optional
// forward-backward round trip check.
#include <vlo/scale/options.h>

#include <opencv2/core/mat.hpp>

#include <vector>

namespace vlo::scale
{
enum class TrackStatus
{
	Ok,
	Lost,  ///< LK did not converge (or the window left the image)
	ForwardBackward,  ///< tracking back into C(i-1) missed the start by more than lk_fb_max_error
	OutOfImage  ///< landed closer than 2 px to the border of C(i)
};

struct Track
{
	cv::Point2f cur;  ///< position in C(i)
	TrackStatus status = TrackStatus::Lost;
	float fb_error = 0;  ///< [px] round-trip error (0 without the check)
};

/// An 8-bit grey image's Lucas-Kanade pyramid: its levels with the border and derivatives LK reads.
struct LkPyramid
{
	std::vector<cv::Mat> levels;
	int max_level = 0;
	bool empty() const { return levels.empty(); }
};
LkPyramid buildLkPyramid(const cv::Mat& grey, const ScaleOptions& opt);

/// Tracking between two pyramids of images of `size`; the rest as below.
std::vector<Track> trackPoints(const LkPyramid& prev, const LkPyramid& cur, cv::Size size,
	const std::vector<cv::Point2f>& pts, const ScaleOptions& opt, const cv::Matx33d& H = cv::Matx33d::zeros());

/// `prev`, `cur`: 8-bit grey images of the same size. `H`, when not empty, is the infinite homography
/// K R K^-1 of the VO rotation: LK starts at H x instead of x (backwards at H^-1 x), which removes the
/// rotational part of the flow and needs no translation, hence no scale.
std::vector<Track> trackPoints(const cv::Mat& prev, const cv::Mat& cur, const std::vector<cv::Point2f>& pts,
	const ScaleOptions& opt, const cv::Matx33d& H = cv::Matx33d::zeros());
}  // namespace vlo::scale
