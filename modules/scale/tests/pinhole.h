#pragma once
// Shared helpers of the scale tests' hand-built geometry: KITTI's camera matrix and its projection.
#include <opencv2/core/types.hpp>

#include <Eigen/Core>

namespace vlo::scale::test
{
/// Camera 0 of KITTI odometry sequence 00.
inline Eigen::Matrix3d kittiK()
{
	Eigen::Matrix3d K;
	K << 718.856, 0, 607.1928, 0, 718.856, 185.2157, 0, 0, 1;
	return K;
}

/// Pixel of the camera-frame point X.
inline cv::Point2f project(const Eigen::Matrix3d& K, const Eigen::Vector3d& X)
{
	const Eigen::Vector3d x = K * X;
	return {static_cast<float>(x.x() / x.z()), static_cast<float>(x.y() / x.z())};
}
}  // namespace vlo::scale::test
