// [lidar]: which times each scan carries into the LiDAR odometry, and its rays' elevation offset.
#include <gtest/gtest.h>
#include <vlo/pipeline/lidar_options.h>

#include <cmath>

namespace vlo::test
{
namespace
{
PointCloud leftAndForward(bool sensor_times)
{
	PointCloud scan;
	scan.push_back(LidarPoint{0.0f, 5.0f, 0.0f, 0.0f, 0.01f});  // left, with a sensor time of 10 ms
	scan.push_back(LidarPoint{5.0f, 0.0f, 0.0f, 0.0f, 0.02f});  // forward
	scan.has_time = sensor_times;
	return scan;
}

PointCloud applied(pipeline::PointTimes mode, bool sensor_times)
{
	pipeline::LidarOptions o;
	o.point_times = mode;
	PointCloud scan = leftAndForward(sensor_times);
	pipeline::applyLidarOptions(scan, o);
	return scan;
}
}  // namespace

TEST(PointTimes, AutoKeepsTheSensorsTimesAndFillsMissingOnesFromTheAzimuth)
{
	const PointCloud kept = applied(pipeline::PointTimes::Auto, true);
	EXPECT_STREQ(pipeline::pointTimeSource(kept), "sensor");
	EXPECT_FLOAT_EQ(kept[0].time, 0.01f);
	const PointCloud filled = applied(pipeline::PointTimes::Auto, false);
	EXPECT_STREQ(pipeline::pointTimeSource(filled), "azimuth");
	EXPECT_NEAR(filled[0].time, -0.025f, 1e-7);  // a quarter turn before the frame's time (forward)
	EXPECT_NEAR(filled[1].time, 0.0f, 1e-7);
}

TEST(PointTimes, EachOtherModeDoesWhatItSays)
{
	EXPECT_STREQ(pipeline::pointTimeSource(applied(pipeline::PointTimes::Sensor, false)), "none");
	EXPECT_FLOAT_EQ(applied(pipeline::PointTimes::Sensor, true)[1].time, 0.02f);
	EXPECT_STREQ(pipeline::pointTimeSource(applied(pipeline::PointTimes::None, true)), "none");
	const PointCloud az = applied(pipeline::PointTimes::Azimuth, true);
	EXPECT_STREQ(pipeline::pointTimeSource(az), "azimuth");
	EXPECT_NEAR(az[1].time, 0.0f, 1e-7);
}

TEST(PointTimes, OptionsGiveTheSweep)
{
	pipeline::LidarOptions o;
	o.clockwise = false;
	o.scan_period = 0.05;
	o.frame_azimuth_deg = 90;
	const SpinningSweep s = o.sweep();
	EXPECT_FALSE(s.clockwise);
	EXPECT_DOUBLE_EQ(s.period, 0.05);
	EXPECT_NEAR(s.timeAt(M_PI / 2), 0.0, 1e-15);
	EXPECT_NEAR(s.timeAt(M_PI), 0.0125, 1e-15);  // counterclockwise: a quarter turn after
}

TEST(LidarOptions, TheElevationOffsetRaisesEveryRayBeforeTheTimes)
{
	pipeline::LidarOptions o;
	o.elevation_offset_deg = 1.0;
	PointCloud scan = leftAndForward(false);
	scan[1].z = -1.0f;  // the ground ahead, 11.3 deg down
	pipeline::applyLidarOptions(scan, o);
	const double e = std::atan2(-1.0, 5.0) + M_PI / 180;
	EXPECT_NEAR(scan[1].x, std::hypot(5.0, 1.0) * std::cos(e), 1e-5);
	EXPECT_NEAR(scan[1].z, std::hypot(5.0, 1.0) * std::sin(e), 1e-5);
	EXPECT_NEAR(scan[0].z, 5 * std::sin(M_PI / 180), 1e-5);  // level to the left: 1 deg up, still left
	EXPECT_NEAR(scan[0].x, 0, 1e-6);
	EXPECT_NEAR(scan[0].time, -0.025f, 1e-7);  // the azimuth, and with it the time, is kept
}
}  // namespace vlo::test
