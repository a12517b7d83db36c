#pragma once
// Ways to keep `want` of a level's FAST corners spread over the image (region w x h).
#include <opencv2/core.hpp>

#include <vector>

namespace vlo::vo::detail
{
/// Stronger response first; ties by position so that results never depend on sort internals.
bool stronger(const cv::KeyPoint& a, const cv::KeyPoint& b);
/// std::sort(kps, stronger), faster (fewer than 2^32 corners).
void sortStrongestFirst(std::vector<cv::KeyPoint>& kps);

/// FAST corners of roi (with non-maximum suppression) at the `strong` threshold, plus those at the
/// `weak` one in the cell x cell squares that have no strong corner (ORB-SLAM's fallback).
std::vector<cv::KeyPoint> detectFast(const cv::Mat& roi, int cell, int strong, int weak);

/// Adaptive non-maximal suppression: the strongest corners, none closer to a stronger kept one
/// than a radius chosen so that `want` remain. Spread like a grid, but shift-invariant: the same
/// corners win when the image moves, which keeps features repeatable. Only the strongest
/// pool * want corners compete.
std::vector<cv::KeyPoint> distributeAnms(std::vector<cv::KeyPoint> kps, int w, int h, int want, double pool);

/// ORB-SLAM's quadtree: the node with most corners is split into four until there are `want`
/// nodes (or none can be split); each node keeps its strongest corner. Dense regions get more.
std::vector<cv::KeyPoint> distributeQuadtree(const std::vector<cv::KeyPoint>& kps, int w, int h, int want);
}  // namespace vlo::vo::detail
