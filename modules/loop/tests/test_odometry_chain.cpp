// The odometry edges' covariance: the frames' covariances composed between keyframes (closed form
// along a straight chain), a registration degenerate along x, and the per-metre model without one.
#include <gtest/gtest.h>
#include <vlo/loop/odometry_chain.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "synthetic_places.h"

using namespace vlo::loop;
using namespace vlo::loop::test;
using vlo::invertPositive;
using vlo::Matrix6d;

namespace
{
Matrix6d diagonal(double t, double r)
{
	return (Eigen::Matrix<double, 6, 1>() << t, t, t, r, r, r).finished().asDiagonal();
}

/// The point-to-plane J^T J ([translation; rotation], rows n^T [I, -[p]x]) of a corridor along x seen
/// from its axis: walls at y = +-4, a floor at z = -1.7; nothing across x.
Matrix6d corridorJtJ(std::size_t& pairs)
{
	Matrix6d JtJ = Matrix6d::Zero();
	pairs = 0;
	const auto add = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
		Eigen::Matrix<double, 6, 1> j;
		j << n, p.cross(n);
		JtJ += j * j.transpose();
		++pairs;
	};
	for (double x = -30; x <= 30; x += 0.5)
		for (double h = -1.5; h <= 3; h += 0.5)
		{
			add({x, 4, h}, {0, -1, 0});
			add({x, -4, h}, {0, 1, 0});
			add({x, h, -1.7}, {0, 0, 1});
		}
	return JtJ;
}
}  // namespace

TEST(OdometryChain, ComposesTheFramesCovariancesBetweenKeyframesAsInClosedForm)
{
	// Five 1.2 m frames along x, each registered to 2 cm and 0.2 deg, plus the floor of 1 cm and
	// 0.05 deg per metre: across the way the keyframe edge's variance is N st^2 + sr^2 s^2 (N - 1) N
	// (2N - 1) / 6 (each turn swings what follows), st and sr the frame's with its floor.
	const int N = 5;
	const double s = 1.2, registered_t = 0.02, registered_r = 0.2 * M_PI / 180;
	const double st = std::hypot(registered_t, 0.01 * s), sr = std::hypot(registered_r, 0.05 * s * M_PI / 180);
	LoopOptions o;
	o.odometry_floor_per_metre = 0.01;
	o.odometry_floor_deg_per_metre = 0.05;
	OdometryChain chain(o);
	const Matrix6d registered = invertPositive(diagonal(registered_t * registered_t, registered_r * registered_r));
	chain.add(pose2d(s, 0, 0), registered);
	(void)chain.take();  // a keyframe: what follows starts anew
	for (int i = 0; i < N; ++i) chain.add(pose2d(s, 0, 0), registered);
	const Matrix6d cov = chain.take();
	EXPECT_NEAR(cov(0, 0), N * st * st, 1e-12);
	EXPECT_NEAR(cov(1, 1), N * st * st + sr * sr * s * s * (N - 1) * N * (2 * N - 1) / 6.0, 1e-12);
	EXPECT_NEAR(cov(1, 5), sr * sr * s * (N - 1) * N / 2.0, 1e-12);
	EXPECT_NEAR(cov(5, 5), N * sr * sr, 1e-12);
	EXPECT_EQ(chain.take(), Matrix6d::Zero());
}

TEST(OdometryChain, ARegistrationDegenerateAlongXGivesAnEdgeWeakAlongX)
{
	std::size_t pairs = 0;
	const Matrix6d JtJ = corridorJtJ(pairs);
	const Matrix6d frame = vlo::registrationInformation(JtJ, pairs, 0.03);
	LoopOptions o;
	o.odometry_floor_per_metre = 0.01;
	OdometryChain chain(o);
	for (int i = 0; i < 3; ++i) chain.add(pose2d(1.0, 0, 0), frame);
	const Matrix6d edge = invertPositive(chain.take());
	const Eigen::SelfAdjointEigenSolver<Matrix6d> es(edge);
	const Eigen::Matrix<double, 6, 1> weakest = es.eigenvectors().col(0);
	EXPECT_NEAR(std::abs(weakest(0)), 1.0, 1e-6) << weakest.transpose();  // pure x
	EXPECT_LT(es.eigenvalues()(0), 1e-6 * es.eigenvalues()(1));
	// Every other direction is held: across the corridor each frame's registration knows the place
	// to 3 cm / sqrt(100 x 2/3) = 3.7 mm, plus the floor's 1 cm: sqrt(3 (3.7^2 + 10^2)) = 18 mm.
	const Matrix6d cov = invertPositive(edge);
	EXPECT_NEAR(std::sqrt(cov(1, 1)), std::sqrt(3 * (0.03 * 0.03 / (100 * 2 / 3.0) + 1e-4)), 1e-3);
}

TEST(OdometryChain, WithoutInformationTheFramesGetThePerMetreModel)
{
	LoopOptions o;
	o.odometry_sigma_per_metre = 0.01;
	o.odometry_sigma_deg_per_metre = 0.05;
	OdometryChain chain(o);
	chain.add(pose2d(2.0, 0, 0), std::nullopt);
	const Matrix6d cov = chain.take();
	EXPECT_NEAR(cov(0, 0), 0.02 * 0.02, 1e-12);
	EXPECT_NEAR(cov(5, 5), std::pow(0.1 * M_PI / 180, 2), 1e-12);
}
