#pragma once
// Robust least squares on a 6-DoF pose by iteratively reweighted Levenberg-Marquardt: each
// iteration weighs the residuals by rho'(s) at the current pose and takes one step on the weighted
// squares (Marquardt's damping at 1e-4 of the diagonal), kept only where the weighted cost drops as
// the model predicts. The rotation is perturbed on the left, the translation added:
// T' = (exp(d_rot) R, t + d_trans). LOAM's line/plane solve and the VO's reprojection solve use it:
// Ceres' per-solve set-up cost three times these small problems (6 unknowns, a few thousand residuals).
#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace vlo
{
/// The robust loss rho of a squared residual s, as its IRLS weight rho'(s): Huber rho(s) = s inside
/// the scale a, 2 a sqrt(s) - a^2 outside; Cauchy rho(s) = a^2 log(1 + s / a^2); none rho(s) = s.
class RobustWeight
{
   public:
	enum Kind
	{
		None,
		Huber,
		Cauchy
	};
	RobustWeight(Kind kind, double scale) : kind_(kind), a_(scale), a2_(a_ * a_), inv_a2_(1.0 / a2_) {}
	double operator()(double s) const
	{
		if (kind_ == Huber) return s > a2_ ? a_ / std::sqrt(s) : 1.0;
		if (kind_ == Cauchy) return 1.0 / (1.0 + s * inv_a2_);
		return 1.0;
	}
	/// rho(s) itself (the robust cost, as Ceres reports it).
	double rho(double s) const
	{
		if (kind_ == Huber) return s > a2_ ? 2 * a_ * std::sqrt(s) - a2_ : s;
		if (kind_ == Cauchy) return a2_ * std::log1p(s * inv_a2_);
		return s;
	}

   private:
	Kind kind_;
	double a_, a2_, inv_a2_;
};

/// J^T W J, J^T W r and the weighted cost 1/2 sum w r^2 over the tangent [rotation, translation].
struct PoseNormalEquations
{
	Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
	Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
	double cost = 0;
};

/// The robust weight of each squared residual.
inline void weigh(const std::vector<double>& s, const RobustWeight& weight, std::vector<double>& w)
{
	w.resize(s.size());
	for (std::size_t i = 0; i < s.size(); ++i) w[i] = weight(s[i]);
}

/// Refines T; returns the iterations taken. Problem provides
///   void squaredResiduals(const Eigen::Isometry3d& T, std::vector<double>& s) const;
///   PoseNormalEquations normalEquations(const std::vector<double>& w, const Eigen::Isometry3d& T) const;
/// with the same residual order in both. Weight is a RobustWeight, or a type with its own
/// weigh(s, weight, w) found by argument-dependent lookup (residuals weighed differently, e.g. a prior's).
template <class Problem, class Weight>
int solveRobustPose(const Problem& problem, const Weight& weight, int max_iterations, Eigen::Isometry3d& T)
{
	std::vector<double> s, s_next, w;  // squared residuals at T and at the step's pose; weights at T
	// Poses composed over many frames drift off SO(3), and a transposed inverse amplifies that.
	T.linear() = Eigen::Quaterniond(T.linear()).normalized().toRotationMatrix();
	problem.squaredResiduals(T, s);
	int it = 0;
	while (it < max_iterations)
	{
		++it;
		weigh(s, weight, w);
		const PoseNormalEquations ne = problem.normalEquations(w, T);
		Eigen::Matrix<double, 6, 6> A = ne.H;
		A.diagonal() += 1e-4 * ne.H.diagonal().cwiseMax(1e-6);
		const Eigen::Matrix<double, 6, 1> d = -A.ldlt().solve(ne.g);
		if (!d.allFinite()) break;
		Eigen::Isometry3d next = T;
		next.linear() = (Eigen::AngleAxisd(d.head<3>().norm(), d.head<3>().normalized()) * Eigen::Quaterniond(T.linear()))
							.normalized()
							.toRotationMatrix();
		next.translation() += d.tail<3>();
		problem.squaredResiduals(next, s_next);
		double cost = 0;
		for (std::size_t i = 0; i < s_next.size(); ++i) cost += w[i] * s_next[i];
		cost *= 0.5;
		const double predicted = -(ne.g.dot(d) + 0.5 * d.dot(ne.H * d));
		if (!(predicted > 0) || ne.cost - cost < 1e-3 * predicted) break;
		T = next;
		s.swap(s_next);  // the next iteration's weights come from these
		if (ne.cost - cost <= 1e-6 * ne.cost) break;  // converged: the weights would not change either
	}
	return it;
}
}  // namespace vlo
