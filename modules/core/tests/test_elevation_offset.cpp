// raiseElevations: every ray turned up by the offset, its range and azimuth kept.
#include <gtest/gtest.h>
#include <vlo/core/elevation_offset.h>

#include <cmath>

using namespace vlo;

TEST(ElevationOffset, RaysTurnUpKeepingRangeAndAzimuth)
{
	PointCloud scan;
	LidarPoint a, b, c;
	a.x = 10, a.y = 0, a.z = 0;  // level, ahead
	b.x = 0, b.y = -8, b.z = -1.73f;  // the ground to the right
	c.x = 0, c.y = 0, c.z = 5;  // straight up: no azimuth, unchanged
	scan = {a, b, c};
	PointCloud out = scan;
	raiseElevations(out, 1.0);
	const double d = M_PI / 180;
	EXPECT_NEAR(out[0].x, 10 * std::cos(d), 1e-5);
	EXPECT_NEAR(out[0].y, 0, 1e-6);
	EXPECT_NEAR(out[0].z, 10 * std::sin(d), 1e-5);
	const double r = std::hypot(8.0, 1.73), e = std::atan2(-1.73, 8.0) + d;
	EXPECT_NEAR(out[1].x, 0, 1e-6);
	EXPECT_NEAR(out[1].y, -r * std::cos(e), 1e-5);
	EXPECT_NEAR(out[1].z, r * std::sin(e), 1e-5);
	EXPECT_EQ(out[2].z, 5.0f);
	PointCloud same = scan;
	raiseElevations(same, 0.0);
	EXPECT_EQ(same[1].z, scan[1].z);
}
