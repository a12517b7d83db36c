#include <vlo/core/se3_twist.h>

#include <cmath>

namespace vlo
{
namespace
{
/// V of the SE(3) exponential, t = V * rho, with W = skew(phi) and theta = |phi|.
Eigen::Matrix3d leftJacobian(const Eigen::Matrix3d& W, double theta)
{
	if (theta < 1e-8) return Eigen::Matrix3d::Identity() + 0.5 * W;
	const double b = (1 - std::cos(theta)) / (theta * theta), c = (theta - std::sin(theta)) / (theta * theta * theta);
	return Eigen::Matrix3d::Identity() + b * W + c * W * W;
}
}  // namespace

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d S;
	S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return S;
}

Eigen::Isometry3d expTwist(const Vector6d& xi)
{
	const Eigen::Vector3d phi = xi.tail<3>();
	const double theta = phi.norm();
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	if (theta > 0) T.linear() = Eigen::AngleAxisd(theta, phi / theta).toRotationMatrix();
	T.translation() = leftJacobian(skew(phi), theta) * xi.head<3>();
	return T;
}

Vector6d logTwist(const Eigen::Isometry3d& T)
{
	const Eigen::AngleAxisd aa(T.linear());
	const Eigen::Vector3d phi = aa.angle() * aa.axis();
	Vector6d xi;
	xi.tail<3>() = phi;
	xi.head<3>() = leftJacobian(skew(phi), aa.angle()).inverse() * T.translation();
	return xi;
}
}  // namespace vlo
