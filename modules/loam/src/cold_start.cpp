#include <vlo/loam/cold_start.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <vector>

namespace vlo::loam
{
namespace
{
constexpr double kInlierDistance = 0.1;  // [m] real KITTI residuals are 2-10 cm (doc/LOAM.md)
constexpr double kAgreement = 0.05;  // [m] results this close are one answer

/// The part of `v` across the line of `e`: the only part the line fixes.
Eigen::Vector3d across(const EdgeMatch& e, const Eigen::Vector3d& v) { return v - e.u * e.u.dot(v); }
bool inlier(const EdgeMatch& e, const Eigen::Isometry3d& T, double tolerance) { return across(e, T * e.p - e.a).norm() <= tolerance; }
bool inlier(const PlaneMatch& p, const Eigen::Isometry3d& T, double tolerance) { return std::abs(p.n.dot(T * p.p) + p.d) <= tolerance; }
}  // namespace

int countInliers(const Matches& m, const Eigen::Isometry3d& T, double tolerance)
{
	int n = 0;
	for (const EdgeMatch& e : m.edges) n += inlier(e, T, tolerance);
	for (const PlaneMatch& p : m.planes) n += inlier(p, T, tolerance);
	return n;
}

double inliersAlong(const Matches& m, const Eigen::Isometry3d& T, double tolerance, const Eigen::Vector3d& d)
{
	double sum = 0;
	for (const EdgeMatch& e : m.edges)
		if (inlier(e, T, tolerance)) sum += across(e, d).squaredNorm();
	for (const PlaneMatch& p : m.planes)
		if (inlier(p, T, tolerance)) sum += p.n.dot(d) * p.n.dot(d);
	return sum;
}

ColdStart searchFirstMotion(const ScanToScanOdometry& odometry, const FeatureSet& curr, double range, double step)
{
	std::vector<Eigen::Vector3d> starts{Eigen::Vector3d::Zero()};
	for (int k = 1; step > 0 && k * step <= range + 1e-9; ++k)
		for (int axis = 0; axis < 2; ++axis)  // x, y
			for (double sign : {1.0, -1.0}) starts.push_back(sign * k * step * Eigen::Vector3d::Unit(axis));
	ColdStart best;
	struct Result
	{
		Eigen::Isometry3d motion;
		Matches matches;
	};
	std::vector<Result> results;
	for (const Eigen::Vector3d& start : starts)
	{
		Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
		guess.translation() = start;
		const ScanToScanOdometry::Result r = odometry.match(curr, guess);
		++best.hypotheses;
		if (!r.ok) continue;
		results.push_back({r.T_prev_curr, {}});
		odometry.findMatches(curr, r.T_prev_curr, results.back().matches);
	}
	if (results.empty()) return best;
	// The level direction in which the results spread most.
	Eigen::Vector2d mean = Eigen::Vector2d::Zero();
	for (const Result& r : results) mean += r.motion.translation().head<2>() / static_cast<double>(results.size());
	Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
	for (const Result& r : results)
	{
		const Eigen::Vector2d x = r.motion.translation().head<2>() - mean;
		scatter += x * x.transpose() / static_cast<double>(results.size());
	}
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(scatter);
	const bool agree = es.eigenvalues()(1) < kAgreement * kAgreement;
	const Eigen::Vector3d d(es.eigenvectors()(0, 1), es.eigenvectors()(1, 1), 0);
	double best_score = -1;
	for (const Result& r : results)
	{
		const int inliers = countInliers(r.matches, r.motion, kInlierDistance);
		const double score = agree ? inliers : inliersAlong(r.matches, r.motion, kInlierDistance, d);
		if (score > best_score) best_score = score, best.inliers = inliers, best.motion = r.motion;
	}
	return best;
}
}  // namespace vlo::loam
