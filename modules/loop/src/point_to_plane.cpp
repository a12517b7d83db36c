#include <vlo/icp/registration.h>
#include <vlo/loop/point_to_plane.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

namespace vlo::loop
{
namespace
{
constexpr double kConvergence = 1e-4;  // update norm that ends the iterations (0.1 mm, 0.1 mrad)

struct System
{
	Matrix6d JtWJ = Matrix6d::Zero(), JtJ = Matrix6d::Zero();
	Vector6d JtWr = Vector6d::Zero();
	std::size_t pairs = 0;
	double sum_r2 = 0;
};

System buildSystem(const icp::Points& scan, const PlaneMap& map, const Eigen::Isometry3d& pose, double gate, double kernel)
{
	System s;
	const double gate2 = gate * gate;
	Eigen::Matrix<double, 1, 6> J;
	std::size_t index = 0;
	double d2 = 0;
	Eigen::Vector3d n;
	for (const auto& p : scan)
	{
		const Eigen::Vector3d rotated = pose.linear() * p, moved = rotated + pose.translation();
		if (!map.nearest(moved, index, d2) || d2 > gate2 || !map.normal(index, n)) continue;
		const double r = n.dot(moved - map.point(index));
		J.leftCols<3>() = n.transpose();
		J.rightCols<3>() = -n.transpose() * skew(rotated);
		const double w = icp::gemanMcClureWeight(r * r, kernel);
		s.JtWJ.noalias() += w * J.transpose() * J;
		s.JtWr.noalias() += w * J.transpose() * r;
		s.JtJ.noalias() += J.transpose() * J;
		s.sum_r2 += r * r;
		++s.pairs;
	}
	return s;
}
}  // namespace

PlaneFit alignPointToPlane(const icp::Points& scan, const PlaneMap& map, const Eigen::Isometry3d& guess, double gate,
	double kernel, int max_iterations)
{
	PlaneFit fit;
	fit.pose = guess;
	for (; fit.iterations < max_iterations; ++fit.iterations)
	{
		const System s = buildSystem(scan, map, fit.pose, gate, kernel);
		if (s.pairs < 6) break;
		// Damped: a direction without planes (a corridor's axis) stays where it is instead of running off.
		const Vector6d dx = (s.JtWJ + 1e-6 * s.JtWJ.trace() * Matrix6d::Identity()).ldlt().solve(-s.JtWr);
		if (!dx.allFinite()) break;
		Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
		step.linear() = Eigen::AngleAxisd(dx.tail<3>().norm(), dx.tail<3>().normalized()).toRotationMatrix();
		if (dx.tail<3>().norm() == 0) step.linear().setIdentity();
		fit.pose.linear() = step.linear() * fit.pose.linear();
		fit.pose.translation() += dx.head<3>();
		if (dx.norm() < kConvergence) break;
	}
	fit.pose.linear() = Eigen::Quaterniond(fit.pose.linear()).normalized().toRotationMatrix();
	const System last = buildSystem(scan, map, fit.pose, gate, kernel);
	fit.information = last.JtJ;
	fit.pairs = last.pairs;
	fit.rms = last.pairs ? std::sqrt(last.sum_r2 / static_cast<double>(last.pairs)) : 0.0;
	return fit;
}

double translationConstraint(const Matrix6d& information)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(information.topLeftCorner<3, 3>());
	const double largest = eig.eigenvalues()(2);
	return largest > 0 ? std::max(0.0, eig.eigenvalues()(0)) / largest : 0.0;
}
}  // namespace vlo::loop
