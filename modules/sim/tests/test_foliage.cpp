// Foliage: beams that hit a crown's hull return from a leaf at an exponential depth inside it.
#include <gtest/gtest.h>
#include <vlo/sim/foliage.h>
#include <vlo/sim/rng.h>

#include <cmath>

using namespace vlo::sim;

namespace
{
const Eigen::Vector3d kOrigin(-10, 0, 2), kAlongX(1, 0, 0);

Foliage sphereCrown()  // radius 2 around (0, 0, 2), smooth hull: the beam along x hits it at 8 m
{
	Foliage f;
	f.add(Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(2, 2, 2), 0.0);
	return f;
}
}  // namespace

TEST(Foliage, DepthInsideTheCrownIsExponentialWithTheConfiguredMean)
{
	const Foliage f = sphereCrown();
	Rng rng(3);
	const int n = 20000;
	double sum = 0;
	int returns = 0;
	for (int i = 0; i < n; ++i)
	{
		double r = 8.0;
		if (!f.penetrate(kOrigin, kAlongX, 0.5, rng, r)) continue;
		++returns;
		ASSERT_GE(r, 8.0);
		ASSERT_LT(r, 12.0);  // never beyond the crown's far side
		sum += r - 8.0;
	}
	// 4 m of crown: a beam passes through with probability exp(-4 / 0.5) = 0.03 %.
	EXPECT_GT(returns, n * 0.995);
	EXPECT_NEAR(sum / returns, 0.5, 0.02);
}

TEST(Foliage, ABeamThatOutrunsTheCrownHasNoReturn)
{
	const Foliage f = sphereCrown();
	Rng rng(4);
	int none = 0;
	const int n = 20000;
	for (int i = 0; i < n; ++i)
	{
		double r = 8.0;
		none += f.penetrate(kOrigin, kAlongX, 4.0, rng, r) ? 0 : 1;
	}
	EXPECT_NEAR(none / double(n), std::exp(-1.0), 0.01);  // P(depth > 4 m) with a 4 m mean
}

TEST(Foliage, OtherSurfacesAndZeroDepthKeepTheirRange)
{
	const Foliage f = sphereCrown();
	Rng rng(5);
	double r = 5.0;  // 3 m in front of the crown: a trunk, a wall
	EXPECT_TRUE(f.penetrate(kOrigin, kAlongX, 0.5, rng, r));
	EXPECT_EQ(r, 5.0);
	r = 8.0;  // on the hull, but foliage switched off
	EXPECT_TRUE(f.penetrate(kOrigin, kAlongX, 0.0, rng, r));
	EXPECT_EQ(r, 8.0);
	const Foliage none;
	EXPECT_TRUE(none.penetrate(kOrigin, kAlongX, 0.5, rng, r));
	EXPECT_EQ(r, 8.0);
}
