#pragma once
// SE(3) exponential and logarithm of twists [translation part; rotation vector]: a constant twist is
// a constant body velocity, the motion model of KISS-ICP's prediction and Gauss-Newton step and of
// the deskews (a vehicle in a turn moves on an arc, not on the chord).
#include <Eigen/Geometry>

namespace vlo
{
using Vector6d = Eigen::Matrix<double, 6, 1>;

Eigen::Matrix3d skew(const Eigen::Vector3d& v);
Eigen::Isometry3d expTwist(const Vector6d& xi);
Vector6d logTwist(const Eigen::Isometry3d& T);
}  // namespace vlo
