#pragma once
// RANSAC over the 1-D per-point scales s_j: a hypothesis is one sample, its inliers are the samples
// within a relative band around it, the estimate is the mean of the best hypothesis's inliers.
#include <cstdint>
#include <vector>

namespace vlo::scale
{
struct RansacResult
{
	bool found = false;  ///< false only for empty input
	double mean = 0;  ///< of the inliers: the frame's scale estimate
	double stddev = 0;  ///< of the inliers (population)
	double hypothesis = 0;  ///< the winning sample
	int n_inliers = 0;
	std::vector<bool> inlier;  ///< per sample
};

/// Inliers of hypothesis h: |s_j - h| <= tolerance * h. Most inliers wins; ties go to the smaller
/// summed deviation. With at most `iterations` samples every sample is tried (exact and free of
/// randomness); otherwise `iterations` samples are drawn with a generator seeded by `seed`.
RansacResult ransacMean(const std::vector<double>& s, double tolerance, int iterations, std::uint32_t seed);
}  // namespace vlo::scale
