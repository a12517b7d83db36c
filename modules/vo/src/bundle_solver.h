#pragma once
// Levenberg-Marquardt on a bundle problem with the points eliminated (Schur complement), without
// Ceres: each iteration weighs the observations by the robust loss at the current estimate (IRLS),
// forms the reduced camera system over the free poses (at most a few tens: dense), solves it and
// back-substitutes the points; a step is kept only where the weighted cost drops.
#include <vlo/vo/bundle_problem.h>

#include <vector>

namespace vlo::vo::detail
{
struct BundleSolveReport
{
	double initial_cost = 0, final_cost = 0;  ///< 1/2 sum of rho(chi2) over the active observations
	int iterations = 0;
};

/// Optimises p.poses (those not `held`) and the points seen by `active` observations, with a Huber
/// loss of scale `huber` on the chi2 of each (0: plain squares).
BundleSolveReport solveBundleLm(
	BundleProblem& p, const std::vector<char>& active, const std::vector<char>& held, double huber, int max_iterations);
}  // namespace vlo::vo::detail
