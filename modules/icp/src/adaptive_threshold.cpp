#include <vlo/core/se3.h>
#include <vlo/icp/adaptive_threshold.h>

#include <cmath>

namespace vlo::icp
{
AdaptiveThreshold::AdaptiveThreshold(double initial_threshold, double min_motion, double max_range)
	: initial_(initial_threshold), min_motion_(min_motion), max_range_(max_range)
{
}

double AdaptiveThreshold::modelError(const Eigen::Isometry3d& deviation) const
{
	const double theta = rotationAngle(deviation.linear());
	return deviation.translation().norm() + 2.0 * max_range_ * std::sin(theta / 2.0);
}

void AdaptiveThreshold::addDeviation(const Eigen::Isometry3d& deviation)
{
	const double e = modelError(deviation);
	if (e <= min_motion_) return;
	sum_squares_ += e * e;
	++samples_;
}

double AdaptiveThreshold::sigma() const
{
	return samples_ == 0 ? initial_ : std::sqrt(sum_squares_ / static_cast<double>(samples_));
}
}  // namespace vlo::icp
