// Residual factors (analytic Jacobians), the robust pose solver and degeneracy detection.
#include <ceres/ceres.h>
#include <gtest/gtest.h>
#include <vlo/loam/degeneracy.h>
#include <vlo/loam/factors.h>
#include <vlo/loam/pose_solver.h>

#include <random>

#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
Eigen::Isometry3d truePose()
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-0.05, Eigen::Vector3d::UnitY()) *
		Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitX()))
					 .toRotationMatrix();
	T.translation() = Eigen::Vector3d(1.2, -0.4, 0.1);
	return T;
}

// Exact matches: source points p whose images T p lie on planes with the given normals, and on
// vertical lines. A fraction are outliers (displaced by up to 1 m).
Matches syntheticMatches(const Eigen::Isometry3d& T, const std::vector<Eigen::Vector3d>& normals, bool with_edges,
	double outliers, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> U(-20, 20), O(-1, 1), F(0, 1);
	Matches m;
	for (int i = 0; i < 300; ++i)
		for (const Eigen::Vector3d& n0 : normals)
		{
			const Eigen::Vector3d n = n0.normalized();
			const Eigen::Vector3d w(U(rng), U(rng), 0.2 * U(rng));
			const double d = -n.dot(w) + (F(rng) < outliers ? O(rng) : 0.0);
			m.planes.push_back(PlaneMatch{T.inverse() * w, n, d});
		}
	if (with_edges)
		for (int i = 0; i < 100; ++i)
		{
			const Eigen::Vector3d w(U(rng), U(rng), 0.1 * U(rng));
			m.edges.push_back(EdgeMatch{T.inverse() * w, w + Eigen::Vector3d(0.01 * U(rng), 0, 3.0), Eigen::Vector3d::UnitZ()});
		}
	return m;
}

// Central differences of a cost function's residuals with respect to both parameter blocks.
void checkJacobians(const ceres::CostFunction& f, const double* q, const double* t)
{
	const int nr = f.num_residuals();
	std::vector<double> r(nr), Jq(nr * 4), Jt(nr * 3), rp(nr), rm(nr);
	const double* x[2] = {q, t};
	double* J[2] = {Jq.data(), Jt.data()};
	ASSERT_TRUE(f.Evaluate(x, r.data(), J));
	for (int b = 0; b < 2; ++b)
		for (int k = 0; k < (b ? 3 : 4); ++k)
		{
			double qq[4] = {q[0], q[1], q[2], q[3]}, tt[3] = {t[0], t[1], t[2]};
			double* v = b ? tt : qq;
			const double h = 1e-6, v0 = v[k];
			v[k] = v0 + h;
			const double* xp[2] = {qq, tt};
			f.Evaluate(xp, rp.data(), nullptr);
			v[k] = v0 - h;
			f.Evaluate(xp, rm.data(), nullptr);
			for (int i = 0; i < nr; ++i)
				EXPECT_NEAR((b ? Jt[i * 3 + k] : Jq[i * 4 + k]), (rp[i] - rm[i]) / (2 * h), 1e-5) << "block " << b << " param " << k << " residual " << i;
		}
}
}  // namespace

TEST(Solver, AnalyticJacobiansMatchNumeric)
{
	const Eigen::Quaterniond q(truePose().rotation());
	const double qc[4] = {q.x(), q.y(), q.z(), q.w()}, t[3] = {0.3, -0.2, 1.0};
	const Matches m = syntheticMatches(truePose(), {{0, 0, 1}, {1, 0.2, 0}}, true, 0.3, 1);
	checkJacobians(EdgeFactor(m.edges[0]), qc, t);
	checkJacobians(PlaneFactor(m.planes[0]), qc, t);
	std::vector<double> we(5), wp(7);
	for (int i = 0; i < 5; ++i) we[i] = 0.1 + 0.2 * i;
	for (int i = 0; i < 7; ++i) wp[i] = 1.0 / (1 + i);
	checkJacobians(BatchFactor(m.edges.data(), we.data(), 5, m.planes.data(), wp.data(), 7), qc, t);
	checkJacobians(BatchFactor(m.edges.data(), nullptr, 5, m.planes.data(), nullptr, 7), qc, t);
}

TEST(Solver, ARobustSolveTakesTheWholeStepFromFarOutsideTheLossScale)
{
	// Matches at the truth, a guess 10 cm and 1 deg off (up to 35 cm at 20 m), Cauchy bending at
	// 5 cm: one solve (4 Ceres iterations) must land on the pose, batched as with one block per
	// match. (Batches whose residuals were sqrt(rho(s)/s) r did not move at all: that residual is
	// concave in the distance, Gauss-Newton over-steps and Levenberg-Marquardt refuses every step.)
	const Eigen::Isometry3d truth = truePose();
	const Matches m = syntheticMatches(truth, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, true, 0.0, 5);
	for (int block : {1, 64})
	{
		SolverOptions o;
		o.loss = "cauchy";
		o.matches_per_block = block;
		Eigen::Isometry3d T = truth * Eigen::Translation3d(0.1, -0.05, 0.0) * Eigen::AngleAxisd(1.0 * M_PI / 180, Eigen::Vector3d::UnitZ());
		solvePose(m, o, T);
		EXPECT_LT(translationError(T, truth), 0.001) << block;
		EXPECT_LT(rotationErrorDeg(T, truth), 0.005) << block;
	}
}

TEST(Solver, RecoversThePoseDespiteOutliers)
{
	const Eigen::Isometry3d truth = truePose();
	const Matches m = syntheticMatches(truth, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, true, 0.2, 3);
	for (int block : {1, 64})
		for (const char* loss : {"huber", "cauchy"})
		{
			SolverOptions o;
			o.loss = loss;
			o.matches_per_block = block;
			o.max_solver_iterations = 10;
			Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
			T.translation() = Eigen::Vector3d(1.0, -0.3, 0.0);
			T.linear() = Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitZ()).toRotationMatrix();
			for (int round = 0; round < 3; ++round) solvePose(m, o, T);
			EXPECT_LT(translationError(T, truth), 0.01) << loss << " " << block;
			EXPECT_LT(rotationErrorDeg(T, truth), 0.05) << loss << " " << block;
		}
}

TEST(Solver, DegeneracyFlagsAnUnconstrainedDirection)
{
	const Eigen::Isometry3d truth = truePose();
	SolverOptions o;
	Eigen::Matrix<double, 6, 6> H;
	double rms = 0;
	// Ground and walls along x only: nothing stops a slide along x.
	{
		const Matches sm = syntheticMatches(truth, {{0, 0, 1}, {0, 1, 0}}, false, 0.0, 4);
		evaluateMatches(sm.edges, sm.planes, o, truth, H, rms);
	}
	const Degeneracy corridor = analyseDegeneracy(H, 10.0);
	EXPECT_TRUE(corridor.degenerate);
	EXPECT_LT(corridor.min_eigenvalue, 1e-6);
	EXPECT_NEAR(std::abs(corridor.weakest(3)), 1.0, 1e-3);  // the x translation
	EXPECT_LT(rms, 1e-9);

	{
		const Matches sm = syntheticMatches(truth, {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}}, false, 0.0, 5);
		evaluateMatches(sm.edges, sm.planes, o, truth, H, rms);
	}
	const Degeneracy box = analyseDegeneracy(H, 10.0);
	EXPECT_FALSE(box.degenerate);
	EXPECT_GT(box.min_translation_eigenvalue, 100.0);
}
}  // namespace vlo::loam::test
