#include "vlo/loam/pose_solver.h"

#include <ceres/ceres.h>
#include <vlo/loam/factors.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>

namespace vlo::loam
{
namespace
{
std::unique_ptr<ceres::LossFunction> makeLoss(const SolverOptions& o)
{
	if (o.loss == "huber") return std::make_unique<ceres::HuberLoss>(o.loss_scale);
	if (o.loss == "cauchy") return std::make_unique<ceres::CauchyLoss>(o.loss_scale);
	return nullptr;
}

/// IRLS weight rho'(s) of the robust loss at squared residual s (1 without a loss).
double robustWeight(const ceres::LossFunction* loss, double s)
{
	if (!loss) return 1.0;
	double rho[3];
	loss->Evaluate(s, rho);
	return rho[1];
}

Eigen::Vector3d edgeResidual(const EdgeMatch& e, const Eigen::Isometry3d& T)
{
	const Eigen::Vector3d d = T * e.p - e.a;
	return d - e.u * e.u.dot(d);
}

double planeResidual(const PlaneMatch& p, const Eigen::Isometry3d& T) { return p.n.dot(T * p.p) + p.d; }

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d m;
	m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return m;
}
}  // namespace

bool roundConverged(const Eigen::Isometry3d& before, const Eigen::Isometry3d& after, const SolverOptions& o)
{
	const Eigen::Isometry3d d = before.inverse() * after;
	return d.translation().norm() < o.converged_translation &&
		Eigen::AngleAxisd(d.rotation()).angle() * 180.0 / M_PI < o.converged_rotation_deg;
}

void evaluateMatches(const std::vector<EdgeMatch>& edges, const std::vector<PlaneMatch>& planes, const SolverOptions& o,
	const Eigen::Isometry3d& T, Eigen::Matrix<double, 6, 6>& JtJ, double& rms)
{
	const auto loss = makeLoss(o);
	const Eigen::Matrix3d R = T.rotation();
	JtJ.setZero();
	double sum2 = 0;
	// Weighted as in the solve, so outliers count as little there as here.
	Eigen::Matrix<double, 3, 6> J;
	for (const EdgeMatch& e : edges)
	{
		const Eigen::Vector3d Rp = R * e.p;
		const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - e.u * e.u.transpose();
		const double s = edgeResidual(e, T).squaredNorm();
		J.leftCols<3>() = -P * skew(Rp);
		J.rightCols<3>() = P;
		JtJ += robustWeight(loss.get(), s) * J.transpose() * J;
		sum2 += s;
	}
	for (const PlaneMatch& p : planes)
	{
		const Eigen::Vector3d Rp = R * p.p;
		const double r = planeResidual(p, T);
		Eigen::Matrix<double, 1, 6> j;
		j.leftCols<3>() = -p.n.transpose() * skew(Rp);
		j.rightCols<3>() = p.n.transpose();
		JtJ += robustWeight(loss.get(), r * r) * j.transpose() * j;
		sum2 += r * r;
	}
	const std::size_t n = edges.size() + planes.size();
	rms = n ? std::sqrt(sum2 / static_cast<double>(n)) : 0.0;
}

SolveReport solvePose(const Matches& m, const SolverOptions& o, Eigen::Isometry3d& T)
{
	SolveReport rep;
	if (m.size() == 0) return rep;
	Eigen::Quaterniond q0(T.rotation());
	double q[4] = {q0.x(), q0.y(), q0.z(), q0.w()};
	double t[3] = {T.translation().x(), T.translation().y(), T.translation().z()};

	// Factors live here, not in the problem: block allocations instead of one per residual
	// (a deque, because cost functions cannot be moved).
	std::deque<EdgeFactor> edges;
	std::deque<PlaneFactor> planes;
	std::deque<BatchFactor> batches;
	std::vector<double> we, wp;  // the batches' weights
	const auto loss = makeLoss(o);
	ceres::EigenQuaternionManifold manifold;

	ceres::Problem::Options po;
	po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
	po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
	po.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
	po.enable_fast_removal = false;
	po.disable_all_safety_checks = true;  // our blocks are well formed; saves a hash lookup each
	ceres::Problem problem(po);
	problem.AddParameterBlock(q, 4, &manifold);
	problem.AddParameterBlock(t, 3);
	const int B = o.matches_per_block;
	const int ne = static_cast<int>(m.edges.size()), np = static_cast<int>(m.planes.size());
	if (B <= 1)
	{
		for (const EdgeMatch& e : m.edges) problem.AddResidualBlock(&edges.emplace_back(e), loss.get(), q, t);
		for (const PlaneMatch& p : m.planes) problem.AddResidualBlock(&planes.emplace_back(p), loss.get(), q, t);
	}
	else
	{
		we.resize(ne), wp.resize(np);
		for (int i = 0; i < ne; i += B)
			problem.AddResidualBlock(&batches.emplace_back(&m.edges[i], &we[i], std::min(B, ne - i), nullptr, nullptr, 0), nullptr, q, t);
		for (int i = 0; i < np; i += B)
			problem.AddResidualBlock(&batches.emplace_back(nullptr, nullptr, 0, &m.planes[i], &wp[i], std::min(B, np - i)), nullptr, q, t);
	}

	ceres::Solver::Options so;
	so.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;  // 6 unknowns: normal equations are cheapest
	so.num_threads = 1;
	so.logging_type = ceres::SILENT;
	so.minimizer_progress_to_stdout = false;
	ceres::Solver::Summary summary;
	if (B <= 1)
	{
		so.max_num_iterations = o.max_solver_iterations;
		ceres::Solve(so, &problem, &summary);
		rep.iterations = static_cast<int>(summary.num_successful_steps + summary.num_unsuccessful_steps);
	}
	else
	{
		// Batched: iteratively reweighted least squares. Each iteration weighs the matches by
		// rho'(s) at the current pose and takes one least-squares step: Ceres' own step with the loss
		// per block (its corrector for rho'' <= 0), and for Huber and Cauchy (rho concave in s) each
		// reweighting lowers the robust cost.
		so.max_num_iterations = 1;
		for (int it = 0; it < o.max_solver_iterations; ++it)
		{
			const Eigen::Isometry3d Ti = Eigen::Translation3d(t[0], t[1], t[2]) * Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized();
			for (int i = 0; i < ne; ++i) we[i] = robustWeight(loss.get(), edgeResidual(m.edges[i], Ti).squaredNorm());
			for (int i = 0; i < np; ++i) wp[i] = robustWeight(loss.get(), std::pow(planeResidual(m.planes[i], Ti), 2));
			ceres::Solve(so, &problem, &summary);
			rep.iterations += static_cast<int>(summary.num_successful_steps + summary.num_unsuccessful_steps);
			if (summary.termination_type == ceres::CONVERGENCE) break;  // the weights would not change
		}
	}
	Eigen::Quaterniond qs(q[3], q[0], q[1], q[2]);
	qs.normalize();
	T.linear() = qs.toRotationMatrix();
	T.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
	evaluateMatches(m.edges, m.planes, o, T, rep.JtJ, rep.rms);
	return rep;
}
}  // namespace vlo::loam
