#pragma once
// Per-pixel tests at a projected LiDAR point (paper III-B-1), on an 8-bit grey image. Callers keep
// (x, y) at least 3 px (FAST) or 1 px (Sobel) inside the image; gradientAt needs 2 px.
#include <opencv2/core/mat.hpp>

#include <array>

namespace vlo::scale
{
/// The 16-pixel Bresenham circle of radius 3, clockwise from the top (FAST numbering 1..16 -> 0..15).
/// Compass pixels: 0 top, 4 right, 8 bottom, 12 left.
extern const std::array<cv::Point, 16> kFastCircle;

/// FAST-9 segment test: at least 9 contiguous circle pixels all brighter than I(p) + t or all
/// darker than I(p) - t.
bool fast9(const cv::Mat& img, int x, int y, int threshold);

/// The FAST-12 pre-test, relaxed for sparse LiDAR. The paper: "calculate the difference in the pixel
/// values between the keypoint and the surrounding four points, and if more than three meet the
/// threshold, our requirements are met". The four points are the compass pixels of the radius-3
/// circle (FAST-12's high-speed test). Our reading: at least `min_count` (3) of them differ from I(p)
/// by more than t. With same_sign false (default) a difference of either sign counts; with same_sign
/// true they must be all brighter or all darker, as in FAST-12 proper, which on our test textures
/// passes about as many pixels as FAST-9 (fewer on the street scene), i.e. is no relaxation; any sign
/// passes 1.7-2x as many. min_count 4 is the literal "more than three".
bool fast12Pretest(const cv::Mat& img, int x, int y, int threshold, int min_count = 3, bool same_sign = false);

/// Sobel 3x3 gradient divided by 8, i.e. grey levels per pixel on a linear ramp.
cv::Point2f sobelGradient(const cv::Mat& img, int x, int y);
/// sobelGradient bilinearly interpolated at a sub-pixel position.
cv::Point2f gradientAt(const cv::Mat& img, cv::Point2f p);
}  // namespace vlo::scale
