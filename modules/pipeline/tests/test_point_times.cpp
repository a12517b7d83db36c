// [lidar] point_times: which times each scan carries into the LiDAR odometry.
#include <gtest/gtest.h>
#include <vlo/pipeline/point_times.h>

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
	pipeline::PointTimeOptions o;
	o.point_times = mode;
	PointCloud scan = leftAndForward(sensor_times);
	pipeline::applyPointTimes(scan, o);
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
	pipeline::PointTimeOptions o;
	o.clockwise = false;
	o.scan_period = 0.05;
	o.frame_azimuth_deg = 90;
	const SpinningSweep s = o.sweep();
	EXPECT_FALSE(s.clockwise);
	EXPECT_DOUBLE_EQ(s.period, 0.05);
	EXPECT_NEAR(s.timeAt(M_PI / 2), 0.0, 1e-15);
	EXPECT_NEAR(s.timeAt(M_PI), 0.0125, 1e-15);  // counterclockwise: a quarter turn after
}
}  // namespace vlo::test
