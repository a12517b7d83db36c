// Point times from the azimuth of a spinning LiDAR's sweep, in closed form.
#include <gtest/gtest.h>
#include <vlo/core/se3_twist.h>
#include <vlo/core/sweep_times.h>

#include <cmath>

namespace vlo::test
{
namespace
{
double deg(double d) { return d * M_PI / 180.0; }
}  // namespace

TEST(SweepTimes, AVelodyneFacingForwardHalfWayThroughItsTurn)
{
	// KITTI: clockwise from behind; forward at the frame's time, left a quarter turn earlier.
	const SpinningSweep s;
	EXPECT_NEAR(s.timeAt(0.0), 0.0, 1e-15);
	EXPECT_NEAR(s.timeAt(deg(90)), -0.025, 1e-15);
	EXPECT_NEAR(s.timeAt(deg(-90)), 0.025, 1e-15);
	EXPECT_NEAR(s.timeAt(deg(179.9)), -0.05 + 0.1 * 0.1 / 360, 1e-12);  // just after the seam
	EXPECT_NEAR(s.timeAt(deg(-179.9)), 0.05 - 0.1 * 0.1 / 360, 1e-12);  // just before it
}

TEST(SweepTimes, DirectionPeriodAndWhereTheFrameFalls)
{
	SpinningSweep s;
	s.clockwise = false;
	EXPECT_NEAR(s.timeAt(deg(90)), 0.025, 1e-15);
	s.period = 0.05;  // 20 Hz
	EXPECT_NEAR(s.timeAt(deg(-90)), -0.0125, 1e-15);
	// A driver that stamps the sweep at its end, facing backwards: every time is before it.
	SpinningSweep end{true, 0.1, M_PI, 1.0};
	EXPECT_NEAR(end.timeAt(deg(179.9)), -0.1 + 0.1 * 0.1 / 360, 1e-12);
	EXPECT_NEAR(end.timeAt(0.0), -0.05, 1e-12);
	EXPECT_NEAR(end.timeAt(deg(-179.9)), -0.1 * 0.1 / 360, 1e-12);
	// The frame's azimuth turned by 30 deg: a point there is at the frame's time.
	SpinningSweep turned;
	turned.frame_azimuth = deg(30);
	EXPECT_NEAR(turned.timeAt(deg(30)), 0.0, 1e-15);
	EXPECT_NEAR(turned.timeAt(deg(-60)), 0.025, 1e-15);
}

TEST(SweepTimes, SetTimesMarksTheScanTimedFromTheAzimuth)
{
	PointCloud scan;
	scan.push_back(LidarPoint{0.0f, 5.0f, 1.0f});  // left
	scan.push_back(LidarPoint{5.0f, 0.0f, 1.0f});  // forward
	setTimesFromAzimuth(scan, SpinningSweep{});
	EXPECT_TRUE(scan.has_time);
	EXPECT_TRUE(scan.time_from_azimuth);
	EXPECT_NEAR(scan[0].time, -0.025f, 1e-7);
	EXPECT_NEAR(scan[1].time, 0.0f, 1e-7);
}
}  // namespace vlo::test

namespace vlo::test
{
TEST(SweepTimes, OnlyTimesThatDifferLeaveSomethingToDeskew)
{
	PointCloud scan;
	scan.push_back(LidarPoint{1.0f, 0.0f, 0.0f});
	scan.push_back(LidarPoint{0.0f, 1.0f, 0.0f});
	EXPECT_FALSE(hasTimeSpread(scan));  // no times
	scan.has_time = true;
	EXPECT_FALSE(hasTimeSpread(scan));  // every time 0: motion-compensated
	scan[1].time = 0.01f;
	EXPECT_TRUE(hasTimeSpread(scan));
}
}  // namespace vlo::test

namespace vlo::test
{
TEST(SweepTimes, MovingToTheFramesTimeFollowsTheMotion)
{
	// 12 m/s forward and 10 deg/s left over 0.1 s: a return 20 m ahead taken 10 ms before the frame's
	// time, when the sensor was 0.12 m behind, lies 19.88 m ahead of it at the frame's time.
	Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
	motion.linear() = Eigen::AngleAxisd(1.0 * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	motion.translation() = Eigen::Vector3d(1.2, 0.0, 0.0);
	PointCloud scan;
	scan.push_back(LidarPoint{20.0f, 0.0f, 0.0f, 0.0f, -0.01f});
	scan.push_back(LidarPoint{0.0f, 10.0f, 0.0f, 0.0f, 0.0f});
	scan.has_time = true;
	const PointCloud taken = scan;
	moveToFrameTime(scan, motion, 0.1);
	for (std::size_t i = 0; i < scan.size(); ++i)
	{
		const Eigen::Vector3d want = expTwist(taken[i].time / 0.1 * logTwist(motion)) *
			Eigen::Vector3d(taken[i].x, taken[i].y, taken[i].z);
		EXPECT_LT((Eigen::Vector3d(scan[i].x, scan[i].y, scan[i].z) - want).norm(), 2e-4) << i;
		EXPECT_EQ(scan[i].time, 0.0f);
	}
	EXPECT_NEAR(scan[0].x, 19.88f, 1e-3f);
}
}  // namespace vlo::test
