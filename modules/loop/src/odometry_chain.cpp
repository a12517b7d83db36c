#include <vlo/loop/odometry_chain.h>
#include <vlo/core/units.h>

#include <algorithm>
#include <cmath>

namespace vlo::loop
{
OdometryChain::OdometryChain(const LoopOptions& options)
	: floor_per_metre_(options.odometry_floor_per_metre),
	  floor_rad_per_metre_(options.odometry_floor_deg_per_metre * kRadPerDeg),
	  sigma_per_metre_(options.odometry_sigma_per_metre),
	  sigma_rad_per_metre_(options.odometry_sigma_deg_per_metre * kRadPerDeg)
{
}

void OdometryChain::add(const Eigen::Isometry3d& motion, const std::optional<Matrix6d>& information)
{
	// The registration's covariance is too small: its residuals are correlated and its model leaves
	// out the de-skew's and the map's errors. A per-metre floor is added (doc/LOOP.md: measured).
	const double distance = motion.translation().norm();
	const Matrix6d step = information
		? Matrix6d(invertPositive(*information) + distanceCovariance(distance, floor_per_metre_, floor_rad_per_metre_))
		: distanceCovariance(distance, sigma_per_metre_, sigma_rad_per_metre_);
	covariance_ = composeCovariance(covariance_, motion_, step, motion);
	motion_ = motion_ * motion;
}

Matrix6d OdometryChain::take()
{
	const Matrix6d out = covariance_;
	covariance_.setZero();
	motion_.setIdentity();
	return out;
}

Matrix6d distanceCovariance(double distance, double sigma_per_metre, double sigma_rad_per_metre, double floor_distance)
{
	const double d = std::max(distance, floor_distance);
	const double st = sigma_per_metre * d, sr = sigma_rad_per_metre * d;
	Matrix6d cov = Matrix6d::Zero();
	cov.diagonal() << st * st, st * st, st * st, sr * sr, sr * sr, sr * sr;
	return cov;
}
}  // namespace vlo::loop
