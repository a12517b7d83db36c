#include <vlo/loam/cold_start.h>

#include <cmath>

namespace vlo::loam
{
namespace
{
constexpr double kInlierDistance = 0.1;  // [m] real KITTI residuals are 2-10 cm (doc/LOAM.md)
}

int countInliers(const Matches& m, const Eigen::Isometry3d& T, double tolerance)
{
	int n = 0;
	for (const EdgeMatch& e : m.edges)
	{
		const Eigen::Vector3d v = T * e.p - e.a;
		n += (v - e.u * e.u.dot(v)).norm() <= tolerance;
	}
	for (const PlaneMatch& p : m.planes) n += std::abs(p.n.dot(T * p.p) + p.d) <= tolerance;
	return n;
}

ColdStart searchFirstMotion(const ScanToScanOdometry& odometry, const FeatureSet& curr, double range, double step)
{
	std::vector<Eigen::Vector3d> starts{Eigen::Vector3d::Zero()};
	for (int k = 1; step > 0 && k * step <= range + 1e-9; ++k)
		for (int axis = 0; axis < 2; ++axis)  // x, y
			for (double sign : {1.0, -1.0}) starts.push_back(sign * k * step * Eigen::Vector3d::Unit(axis));
	ColdStart best;
	best.inliers = -1;
	Matches m;
	for (const Eigen::Vector3d& start : starts)
	{
		Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
		guess.translation() = start;
		const ScanToScanOdometry::Result r = odometry.match(curr, guess);
		++best.hypotheses;
		if (!r.ok) continue;
		odometry.findMatches(curr, r.T_prev_curr, m);
		const int inliers = countInliers(m, r.T_prev_curr, kInlierDistance);
		if (inliers > best.inliers) best.inliers = inliers, best.motion = r.T_prev_curr;
	}
	best.inliers = std::max(best.inliers, 0);
	return best;
}
}  // namespace vlo::loam
