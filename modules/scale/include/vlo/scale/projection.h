#pragma once
// Eq. 1: x_j = (1/d_j) K T_L^C p_j. The measured depth d_j is the z coordinate of the LiDAR point in
// the camera optical frame (its depth along the optical axis), the same definition as the visual
// depth v_j from triangulation, so that s_j = d_j / v_j compares like with like.
#include <vlo/core/frame.h>

#include <opencv2/core/types.hpp>

#include <Eigen/Geometry>
#include <vector>

namespace vlo::scale
{
struct DepthPixel
{
	cv::Point2f px;  ///< sub-pixel position in C(i-1); pixel centres at integer coordinates
	float depth = 0;  ///< d_j [m], z in the camera optical frame
	int index = -1;  ///< of the point in the scan
};

/// Points of `scan` (LiDAR frame) with depth in [min_depth, max_depth] (max_depth 0: no limit) that
/// land at least `border` pixels inside the image.
std::vector<DepthPixel> projectScan(const PointCloud& scan, const PinholeCamera& cam,
	const Eigen::Isometry3d& camera_T_lidar, double min_depth, double max_depth, int border);
}  // namespace vlo::scale
