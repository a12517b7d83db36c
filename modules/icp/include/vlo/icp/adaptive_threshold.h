#pragma once
// KISS-ICP's adaptive correspondence threshold (paper, section III-C): sigma is the RMS of the
// "model deviations" seen so far, each the pose error of the motion prediction (prediction^-1 * result)
// turned into a point displacement bound: |t| + 2 * max_range * sin(theta / 2), what the deviation
// moves a point at max_range by at most. Deviations below min_motion (standing still) are not counted;
// until one is, sigma is the initial threshold.
#include <Eigen/Geometry>
#include <cstddef>

namespace vlo::icp
{
class AdaptiveThreshold
{
   public:
	AdaptiveThreshold(double initial_threshold, double min_motion, double max_range);

	/// Point displacement bound of a pose deviation [m].
	double modelError(const Eigen::Isometry3d& deviation) const;
	void addDeviation(const Eigen::Isometry3d& deviation);
	/// The current sigma [m]: correspondences are searched within 3 sigma (IcpOdometry sets the kernel).
	double sigma() const;
	std::size_t samples() const { return samples_; }

   private:
	double initial_, min_motion_, max_range_;
	double sum_squares_ = 0;
	std::size_t samples_ = 0;
};
}  // namespace vlo::icp
