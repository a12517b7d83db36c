// The robust pose solver (its normal equations, convergence, outliers) and degeneracy detection.
#include <gtest/gtest.h>
#include <vlo/loam/degeneracy.h>
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

// The distances of all matches at T stacked (3 per edge: the vector from the line; 1 per plane).
Eigen::VectorXd residuals(const Matches& m, const Eigen::Isometry3d& T)
{
	Eigen::VectorXd r(3 * m.edges.size() + m.planes.size());
	int row = 0;
	for (const EdgeMatch& e : m.edges)
	{
		const Eigen::Vector3d d = T * e.p - e.a;
		r.segment<3>(row) = d - e.u * e.u.dot(d);
		row += 3;
	}
	for (const PlaneMatch& p : m.planes) r[row++] = p.n.dot(T * p.p) + p.d;
	return r;
}
}  // namespace

TEST(Solver, NormalMatrixIsTheGaussNewtonMatrixOfTheDistances)
{
	// Without a loss, evaluateMatches' J^T J must be J^T J of the stacked distances, J by central
	// differences over [rotation applied on the left, translation].
	const Eigen::Isometry3d truth = truePose();
	const Matches m = syntheticMatches(truth, {{0, 0, 1}, {1, 0.2, 0}}, true, 0.3, 1);
	Eigen::Isometry3d T = truth * Eigen::Translation3d(0.3, -0.2, 0.1) * Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY());
	SolverOptions o;
	o.loss = "none";
	Eigen::Matrix<double, 6, 6> H;
	double rms = 0;
	evaluateMatches(m.edges, m.planes, o, T, H, rms);
	Eigen::MatrixXd J(residuals(m, T).size(), 6);
	const double h = 1e-6;
	for (int k = 0; k < 6; ++k)
	{
		Eigen::Isometry3d Tp = T, Tm = T;
		if (k < 3)
		{
			Tp.linear() = Eigen::AngleAxisd(h, Eigen::Vector3d::Unit(k)) * T.linear();
			Tm.linear() = Eigen::AngleAxisd(-h, Eigen::Vector3d::Unit(k)) * T.linear();
		}
		else
			Tp.translation()[k - 3] += h, Tm.translation()[k - 3] -= h;
		J.col(k) = (residuals(m, Tp) - residuals(m, Tm)) / (2 * h);
	}
	const Eigen::MatrixXd JtJ = J.transpose() * J;
	EXPECT_LT((H - JtJ).norm(), 1e-6 * JtJ.norm());
	EXPECT_NEAR(rms, std::sqrt(residuals(m, T).squaredNorm() / static_cast<double>(m.size())), 1e-12);
}

TEST(Solver, StartsFromARotationOffSO3)
{
	// A pose composed over many frames drifts off SO(3); the solve must not carry a 1 % scale along.
	const Eigen::Isometry3d truth = truePose();
	const Matches m = syntheticMatches(truth, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, false, 0.0, 6);
	SolverOptions o;
	Eigen::Isometry3d T = truth * Eigen::Translation3d(0.05, 0.02, 0.0);
	T.linear() *= 1.01;
	solvePose(m, o, T);
	EXPECT_LT((T.linear().transpose() * T.linear() - Eigen::Matrix3d::Identity()).norm(), 1e-9);
	EXPECT_LT(translationError(T, truth), 0.001);
	EXPECT_LT(rotationErrorDeg(T, truth), 0.005);
}

TEST(Solver, ARobustSolveTakesTheWholeStepFromFarOutsideTheLossScale)
{
	// Matches at the truth, a guess 10 cm and 1 deg off (up to 35 cm at 20 m), Cauchy bending at
	// 5 cm: one solve (4 reweighted iterations) must land on the pose. (Residuals sqrt(rho(s)/s) r
	// did not move at all: that residual is concave in the distance, Gauss-Newton over-steps and
	// Levenberg-Marquardt refuses every step; reweighting takes the whole step.)
	const Eigen::Isometry3d truth = truePose();
	const Matches m = syntheticMatches(truth, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, true, 0.0, 5);
	SolverOptions o;
	o.loss = "cauchy";
	Eigen::Isometry3d T = truth * Eigen::Translation3d(0.1, -0.05, 0.0) * Eigen::AngleAxisd(1.0 * M_PI / 180, Eigen::Vector3d::UnitZ());
	const SolveReport rep = solvePose(m, o, T);
	EXPECT_LT(translationError(T, truth), 0.001);
	EXPECT_LT(rotationErrorDeg(T, truth), 0.005);
	EXPECT_LE(rep.iterations, o.max_solver_iterations);
}

TEST(Solver, RecoversThePoseDespiteOutliers)
{
	const Eigen::Isometry3d truth = truePose();
	const Matches m = syntheticMatches(truth, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, true, 0.2, 3);
	for (const char* loss : {"huber", "cauchy"})
	{
		SolverOptions o;
		o.loss = loss;
		o.max_solver_iterations = 10;
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.translation() = Eigen::Vector3d(1.0, -0.3, 0.0);
		T.linear() = Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitZ()).toRotationMatrix();
		for (int round = 0; round < 3; ++round) solvePose(m, o, T);
		EXPECT_LT(translationError(T, truth), 0.01) << loss;
		EXPECT_LT(rotationErrorDeg(T, truth), 0.05) << loss;
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
