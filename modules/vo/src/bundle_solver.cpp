#include "bundle_solver.h"

#include <vlo/core/robust_pose_solver.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <vector>

#include "reprojection_error.h"

namespace vlo::vo::detail
{
namespace
{
using Mat63 = Eigen::Matrix<double, 6, 3>;
using Mat26 = Eigen::Matrix<double, 2, 6, Eigen::RowMajor>;
using Mat23 = Eigen::Matrix<double, 2, 3, Eigen::RowMajor>;

/// One observation linearised at the current estimate.
struct Linearised
{
	Eigen::Vector2d r;
	Mat26 Jp;
	Mat23 Jx;
	double w = 1;  ///< IRLS weight
};

class Solver
{
   public:
	Solver(BundleProblem& p, const std::vector<char>& active, const std::vector<char>& held, double huber)
		: p_(p), weight_(huber > 0 ? RobustWeight::Huber : RobustWeight::None, huber), rotations_(p.poses.size())
	{
		// Free poses and points, numbered; each point's active observations.
		pose_slot_.assign(p.poses.size(), -1);
		for (std::size_t i = 0; i < p.poses.size(); ++i)
			if (!held[i]) pose_slot_[i] = n_free_++;
		point_obs_.resize(p.points.size());
		for (std::size_t o = 0; o < p.obs.size(); ++o)
			if (active[o])
			{
				obs_.push_back(o);
				point_obs_[p.obs[o].point].push_back(obs_.size() - 1);
				errors_.emplace_back(p.obs[o].px, p.obs[o].inv_scale, p.cam, &rotations_, p.obs[o].pose);
			}
		lin_.resize(obs_.size());
	}

	BundleSolveReport run(int max_iterations)
	{
		BundleSolveReport rep;
		double cost = linearise();
		rep.initial_cost = robustCost();
		double lambda = 1e-4;
		for (int it = 0; it < max_iterations; ++it)
		{
			++rep.iterations;
			const auto saved_poses = p_.poses;
			const auto saved_points = p_.points;
			if (!step(lambda)) break;
			const double next = weightedCost();
			if (next < cost)
			{
				const double gain = (cost - next) / std::max(cost, 1e-300);
				lambda = std::max(lambda / 10, 1e-12);
				cost = linearise();
				if (gain < 1e-6) break;  // Ceres' function tolerance
			}
			else
			{
				p_.poses = saved_poses, p_.points = saved_points;
				lambda *= 10;
				if (lambda > 1e8) break;
			}
		}
		rep.final_cost = robustCost();
		return rep;
	}

   private:
	/// Residuals and Jacobians at the current estimate; the IRLS weights; returns the weighted cost.
	double linearise()
	{
		double cost = 0;
		for (std::size_t k = 0; k < obs_.size(); ++k)
		{
			const auto& o = p_.obs[obs_[k]];
			Linearised& l = lin_[k];
			const double* params[2] = {p_.poses[o.pose].data(), p_.points[o.point].data()};
			double* jac[2] = {l.Jp.data(), l.Jx.data()};
			errors_[k].Evaluate(params, l.r.data(), jac);
			const double s = l.r.squaredNorm();
			l.w = weight_(s);
			cost += 0.5 * l.w * s;
		}
		return cost;
	}

	/// The chi2 of active observation k at the current estimate.
	double squaredResidual(std::size_t k)
	{
		const auto& o = p_.obs[obs_[k]];
		const double* params[2] = {p_.poses[o.pose].data(), p_.points[o.point].data()};
		Eigen::Vector2d r;
		errors_[k].Evaluate(params, r.data(), nullptr);
		return r.squaredNorm();
	}

	/// 1/2 sum w r^2 at the current estimate with the weights of the last linearisation.
	double weightedCost()
	{
		double cost = 0;
		for (std::size_t k = 0; k < obs_.size(); ++k) cost += 0.5 * lin_[k].w * squaredResidual(k);
		return cost;
	}

	/// 1/2 sum rho(r^2) at the current estimate.
	double robustCost()
	{
		double cost = 0;
		for (std::size_t k = 0; k < obs_.size(); ++k) cost += 0.5 * weight_.rho(squaredResidual(k));
		return cost;
	}

	/// One damped Gauss-Newton step (Marquardt: the diagonal times 1 + lambda), applied to p_.
	bool step(double lambda)
	{
		const int n = 6 * n_free_;
		Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
		Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
		// Pose blocks of J^T W J and -J^T W r.
		for (std::size_t k = 0; k < obs_.size(); ++k)
		{
			const int a = pose_slot_[p_.obs[obs_[k]].pose];
			if (a < 0) continue;
			const Linearised& l = lin_[k];
			S.block<6, 6>(6 * a, 6 * a).noalias() += l.w * l.Jp.transpose() * l.Jp;
			b.segment<6>(6 * a).noalias() -= l.w * l.Jp.transpose() * l.r;
		}
		for (int i = 0; i < n; ++i) S(i, i) *= 1 + lambda;
		// Each point eliminated: S -= H_pl H_ll^-1 H_lp, b -= H_pl H_ll^-1 b_l.
		hll_inv_.resize(p_.points.size());
		bl_.resize(p_.points.size());
		std::vector<Mat63> hpl;
		std::vector<int> slot;
		for (std::size_t pt = 0; pt < p_.points.size(); ++pt)
		{
			const auto& list = point_obs_[pt];
			if (list.empty()) continue;
			Eigen::Matrix3d hll = Eigen::Matrix3d::Zero();
			Eigen::Vector3d bl = Eigen::Vector3d::Zero();
			hpl.clear(), slot.clear();
			for (std::size_t k : list)
			{
				const Linearised& l = lin_[k];
				hll.noalias() += l.w * l.Jx.transpose() * l.Jx;
				bl.noalias() -= l.w * l.Jx.transpose() * l.r;
				const int a = pose_slot_[p_.obs[obs_[k]].pose];
				if (a < 0) continue;
				hpl.push_back(l.w * l.Jp.transpose() * l.Jx);
				slot.push_back(a);
			}
			for (int i = 0; i < 3; ++i) hll(i, i) *= 1 + lambda;
			const Eigen::Matrix3d inv = hll.inverse();
			hll_inv_[pt] = inv;
			bl_[pt] = bl;
			if (!inv.allFinite()) continue;  // a point seen along one ray only: left where it is
			for (std::size_t u = 0; u < hpl.size(); ++u)
			{
				const Mat63 t = hpl[u] * inv;
				b.segment<6>(6 * slot[u]).noalias() -= t * bl;
				for (std::size_t v = 0; v < hpl.size(); ++v)
					S.block<6, 6>(6 * slot[u], 6 * slot[v]).noalias() -= t * hpl[v].transpose();
			}
		}
		Eigen::VectorXd dp = Eigen::VectorXd::Zero(n);
		if (n > 0)
		{
			const Eigen::LDLT<Eigen::MatrixXd> ldlt(S);
			if (ldlt.info() != Eigen::Success) return false;
			dp = ldlt.solve(b);
			if (!dp.allFinite()) return false;
		}
		for (std::size_t i = 0; i < p_.poses.size(); ++i)
			if (pose_slot_[i] >= 0)
				for (int c = 0; c < 6; ++c) p_.poses[i][c] += dp(6 * pose_slot_[i] + c);
		// Back-substitution: H_ll dx = b_l - H_lp dp.
		for (std::size_t pt = 0; pt < p_.points.size(); ++pt)
		{
			const auto& list = point_obs_[pt];
			if (list.empty() || !hll_inv_[pt].allFinite()) continue;
			Eigen::Vector3d rhs = bl_[pt];
			for (std::size_t k : list)
			{
				const int a = pose_slot_[p_.obs[obs_[k]].pose];
				if (a < 0) continue;
				const Linearised& l = lin_[k];
				rhs.noalias() -= l.w * l.Jx.transpose() * (l.Jp * dp.segment<6>(6 * a));
			}
			const Eigen::Vector3d dx = hll_inv_[pt] * rhs;
			for (int c = 0; c < 3; ++c) p_.points[pt][c] += dx(c);
		}
		return true;
	}

	BundleProblem& p_;
	RobustWeight weight_;
	PoseRotations rotations_;
	int n_free_ = 0;
	std::vector<int> pose_slot_;  ///< per pose: its block in the reduced system, -1 if held
	std::vector<std::size_t> obs_;  ///< the active observations
	std::vector<std::vector<std::size_t>> point_obs_;  ///< per point: indices into obs_
	std::vector<ReprojectionError> errors_;
	std::vector<Linearised> lin_;
	std::vector<Eigen::Vector3d> bl_;
	std::vector<Eigen::Matrix3d> hll_inv_;
};
}  // namespace

BundleSolveReport solveBundleLm(
	BundleProblem& p, const std::vector<char>& active, const std::vector<char>& held, double huber, int max_iterations)
{
	return Solver(p, active, held, huber).run(max_iterations);
}
}  // namespace vlo::vo::detail
