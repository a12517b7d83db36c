// Pose-only optimisation of a tracked frame (ORB-SLAM's PoseOptimization with Ceres).
#include <vlo/vo/optimizer.h>

#include "reprojection_error.h"

#include <deque>

namespace vlo::vo
{
int optimizePose(TrackedFrame& f, const PinholeCamera& cam, const ScalePyramid& pyr, int rounds, int iterations,
	double chi2)
{
	std::vector<std::size_t> idx;
	for (std::size_t i = 0; i < f.size(); ++i)
	{
		f.outlier[i] = 0;
		if (f.points[i] && !f.points[i]->bad) idx.push_back(i);
	}
	if (idx.size() < 3) return 0;
	double pose[6];
	detail::toParams(f.Tcw, pose);
	ceres::HuberLoss huber(std::sqrt(chi2));
	const auto solver = detail::solverOptions(iterations, false);
	int inliers = static_cast<int>(idx.size());
	for (int round = 0; round < rounds; ++round)
	{
		std::deque<detail::PoseOnlyError> residuals;
		ceres::Problem problem(detail::problemOptions());
		int n = 0;
		for (std::size_t i : idx)
		{
			if (f.outlier[i]) continue;
			const cv::KeyPoint& k = f.feat->keys[i];
			// Robust only in the first rounds: once outliers are marked, plain least squares.
			problem.AddResidualBlock(&residuals.emplace_back(f.points[i]->pos, Vec2(k.pt.x, k.pt.y),
										 pyr.inv_scale[static_cast<std::size_t>(k.octave)], cam),
				round < 2 ? &huber : nullptr, pose);
			++n;
		}
		if (n < 3) break;
		ceres::Solver::Summary summary;
		ceres::Solve(solver, &problem, &summary);
		const SE3 T = detail::fromParams(pose);
		inliers = 0;
		for (std::size_t i : idx)
		{
			const cv::KeyPoint& k = f.feat->keys[i];
			const Vec3 Xc = T * f.points[i]->pos;
			const double e2 = Xc.z() > 0 ? (project(cam, Xc) - Vec2(k.pt.x, k.pt.y)).squaredNorm() *
											   pyr.inv_sigma2[static_cast<std::size_t>(k.octave)]
										 : 1e18;
			f.outlier[i] = e2 > chi2 ? 1 : 0;
			if (!f.outlier[i]) ++inliers;
		}
		if (inliers < 10) break;
	}
	f.Tcw = detail::fromParams(pose);
	return inliers;
}
}  // namespace vlo::vo
