// Keyframes: which frames are taken, and their scans de-skewed, thinned and in the vehicle frame; and
// LoopClosure's life: options checked, the thread joined without finish().
#include <gtest/gtest.h>
#include <vlo/loop/keyframe.h>
#include <vlo/loop/loop_closure.h>

#include "synthetic_places.h"

using namespace vlo;
using namespace vlo::loop;
using namespace vlo::loop::test;

TEST(KeyframeSelector, TakesTheFirstThenEveryDistanceOrAngle)
{
	KeyframeSelector take(2.0, 15 * M_PI / 180);
	EXPECT_TRUE(take.take(pose2d(0, 0, 0)));
	EXPECT_FALSE(take.take(pose2d(1.9, 0, 0)));
	EXPECT_TRUE(take.take(pose2d(2.0, 0, 0)));
	EXPECT_FALSE(take.take(pose2d(2.5, 0, 14 * M_PI / 180)));
	EXPECT_TRUE(take.take(pose2d(2.5, 0, 16 * M_PI / 180)));
}

TEST(KeyframeScan, ThinsDeskewsAndMovesIntoTheVehicleFrame)
{
	Eigen::Isometry3d vehicle_T_lidar = Eigen::Isometry3d::Identity();
	vehicle_T_lidar.translation() = Eigen::Vector3d(0.5, 0, 2);
	PointCloud scan;
	scan.has_time = true;
	// Two points in one 0.5 m voxel (the second is dropped), one taken 0.05 s before the frame's time.
	scan.push_back(LidarPoint{10.1f, 0.1f, 0.1f, 0, 0.0f});
	scan.push_back(LidarPoint{10.2f, 0.2f, 0.2f, 0, 0.0f});
	scan.push_back(LidarPoint{-10.1f, 0.1f, 0.1f, 0, -0.05f});
	// The LiDAR moved 1 m forward over the 0.1 s frame interval: the early point is 0.5 m behind where
	// the frame's LiDAR would have seen it.
	const ScanPoints pts = keyframeScan(scan, pose2d(1, 0, 0), 0.1, vehicle_T_lidar, 0.5);
	ASSERT_EQ(pts.size(), 2u);
	EXPECT_NEAR(pts[0].x(), 10.6f, 1e-5);
	EXPECT_NEAR(pts[0].z(), 2.1f, 1e-5);
	EXPECT_NEAR(pts[1].x(), -10.1f - 0.5f + 0.5f, 1e-5);
	// Without point times the scan is taken as it is.
	scan.has_time = false;
	EXPECT_NEAR(keyframeScan(scan, pose2d(1, 0, 0), 0.1, vehicle_T_lidar, 0.5)[1].x(), -10.1f + 0.5f, 1e-5);
}

TEST(LoopClosure, WithoutFinishTheDestructorJoins)
{
	LoopClosure loop{LoopOptions{}};
	loop.addFrame(0, 0.0, pose2d(0, 0, 0), std::nullopt, PointCloud{}, Eigen::Isometry3d::Identity());
	EXPECT_EQ(loop.keyframes(), 1u);
}

TEST(LoopClosure, RefusesOptionsOutOfRange)
{
	LoopOptions bad;
	bad.descriptor_rings = 1;
	EXPECT_THROW(LoopClosure{bad}, OptionError);
}
