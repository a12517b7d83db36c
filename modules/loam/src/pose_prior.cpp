#include <vlo/loam/pose_prior.h>

#include <vlo/core/units.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace vlo::loam
{
Vector6d PosePrior::residual(const Eigen::Isometry3d& T) const
{
	const Eigen::AngleAxisd rot(T.linear() * pose.linear().transpose());
	Vector6d r;
	r.head<3>() = rot.angle() * rot.axis();
	r.tail<3>() = T.translation() - pose.translation();
	return r;
}

double PosePrior::squaredMahalanobis(const Eigen::Isometry3d& T) const
{
	const Vector6d r = residual(T);
	return r.dot(information * r);
}

PosePrior posePriorInScanAxes(
	const Eigen::Isometry3d& pose, const Eigen::Matrix3d& rotation_information, const Eigen::Matrix3d& translation_information)
{
	PosePrior p;
	p.pose = pose;
	const Eigen::Matrix3d R = pose.linear();
	p.information.topLeftCorner<3, 3>() = R * rotation_information * R.transpose();
	p.information.bottomRightCorner<3, 3>() = R * translation_information * R.transpose();
	return p;
}
PosePrior externalMotionPrior(const Eigen::Isometry3d& previous_pose, const Eigen::Isometry3d& motion,
	const ExternalMotionQuality& quality, const PriorOptions& o, double match_sigma)
{
	// Fewer features tracked, less certain; an unknown count is taken as full quality.
	const double tracked = std::isfinite(quality.tracked) ? std::max(quality.tracked, 1.0) : o.full_quality_tracked;
	const double inflate = std::max(1.0, o.full_quality_tracked / tracked);
	const double sigma2 = o.motion_sigma * o.motion_sigma * inflate;
	const double m2 = match_sigma * match_sigma;
	Eigen::Matrix3d cov_t = sigma2 * Eigen::Matrix3d::Identity();
	const double length = motion.translation().norm();
	if (std::isfinite(quality.length_error) && length > 0)
	{
		const Eigen::Vector3d u = motion.translation() / length;
		cov_t += std::pow(length * quality.length_error, 2) * u * u.transpose();
	}
	const double tilt = o.motion_sigma_deg * kRadPerDeg, yaw = o.motion_sigma_yaw_deg * kRadPerDeg;
	const Eigen::Vector3d rot_info(m2 / (tilt * tilt * inflate), m2 / (tilt * tilt * inflate), m2 / (yaw * yaw * inflate));
	return posePriorInScanAxes(previous_pose * motion, rot_info.asDiagonal(), m2 * cov_t.inverse());
}

double geometryCostOfPrior(const PosePrior& prior, const Matrix6d& matches_JtJ, const Eigen::Isometry3d& T)
{
	const Vector6d pull = prior.information * prior.residual(T);
	// A tiny ridge keeps a direction the matches leave free finite (it then costs them nothing).
	Matrix6d H = matches_JtJ;
	H.diagonal().array() += 1e-9 * std::max(H.trace(), 1.0);
	return pull.dot(H.ldlt().solve(pull));
}
}  // namespace vlo::loam
