// Sun shadows: a crown between a point and the sun shades it (with leaf gaps), the camera tile's
// pixels are scaled by their light, and the avenue scenario is known by name.
#include <gtest/gtest.h>
#include <vlo/sim/config.h>
#include <vlo/sim/sun_shadows.h>

#include <cmath>

using namespace vlo::sim;

namespace
{
Foliage crownAt6m()  // a smooth crown of radius 2 m, 6 m above the origin
{
	Foliage f;
	f.add(Eigen::Vector3d(0, 0, 6), Eigen::Vector3d(2, 2, 2), 0.0);
	return f;
}
}  // namespace

TEST(SunShadows, ACrownBetweenThePointAndTheSunShadesIt)
{
	const Foliage f = crownAt6m();
	const Eigen::Vector3d up(0, 0, 1);
	EXPECT_TRUE(f.shades(Eigen::Vector3d(0, 0, 0), up, 0.0));  // no gaps: straight below is shade
	EXPECT_FALSE(f.shades(Eigen::Vector3d(3, 0, 0), up, 0.0));  // beside the crown: sun
	EXPECT_FALSE(f.shades(Eigen::Vector3d(0, 0, 0), up, 1.0));  // all gap: sun everywhere
	// A low sun from +x: the shadow falls 6 m towards -x.
	const Eigen::Vector3d east = Eigen::Vector3d(1, 0, 1).normalized();
	EXPECT_TRUE(f.shades(Eigen::Vector3d(-6, 0, 0), east, 0.0));
	EXPECT_FALSE(f.shades(Eigen::Vector3d(0, 0, 0), east, 0.0));
	// A point on the crown's own hull facing the sun is lit; the far side is in its own shadow.
	EXPECT_FALSE(f.shades(Eigen::Vector3d(0, 0, 8), up, 0.0));
	EXPECT_TRUE(f.shades(Eigen::Vector3d(0, 0, 4), up, 0.0));
}

TEST(SunShadows, LeafGapsLetSunflecksThroughTheShadow)
{
	const Foliage f = crownAt6m();
	int shaded = 0, n = 0;
	for (double x = -1.0; x <= 1.0; x += 0.05)
		for (double y = -1.0; y <= 1.0; y += 0.05, ++n) shaded += f.shades(Eigen::Vector3d(x, y, 0), Eigen::Vector3d(0, 0, 1), 0.3);
	// The noise is below 0.3 on a minority of the hull: mostly shade, with flecks.
	EXPECT_GT(shaded, n * 0.6);
	EXPECT_LT(shaded, n * 0.99);
}

TEST(SunShadows, TilePixelsAreScaledByTheirLight)
{
	const Foliage f = crownAt6m();
	View v;  // looking straight down from 1 m above the origin at the ground (z = 0)
	v.world_T_cam = Eigen::Isometry3d::Identity();
	v.world_T_cam.linear() << 1, 0, 0, 0, -1, 0, 0, 0, -1;
	v.world_T_cam.translation() = Eigen::Vector3d(0, 0, 1);
	v.K.fx = v.K.fy = 1, v.K.cx = 0, v.K.cy = 0, v.K.width = 2, v.K.height = 1;
	RenderedView t;
	t.width = 2, t.height = 1;
	t.depth = {1.0f, 0.0f};  // pixel 0: the ground below the crown; pixel 1: sky
	t.gray = {100, 100};
	SunLight sun;
	sun.elevation_deg = 90, sun.gap_fraction = 0;
	applySunShadows(t, v, f, sun);
	EXPECT_EQ(t.gray[0], 40);  // 100 x 0.4 in the crown's shadow
	EXPECT_EQ(t.gray[1], 100);  // sky untouched
	// Beside the crown (pixel 0 at x = 4 m): lit, and bright texture clips at 255.
	t.depth = {1.0f, 0.0f};
	t.gray = {200, 100};
	v.world_T_cam.translation() = Eigen::Vector3d(4, 0, 1);
	applySunShadows(t, v, f, sun);
	EXPECT_EQ(t.gray[0], 255);
	EXPECT_NEAR(sun.toSun().norm(), 1.0, 1e-12);
}

TEST(SunShadows, AvenueIsAScenario)
{
	EXPECT_EQ(parseScenario("avenue"), Scenario::Avenue);
	EXPECT_EQ(scenarioName(Scenario::Avenue), "avenue");
}
