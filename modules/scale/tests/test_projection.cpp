// Eq. 1: projection of the scan into C(i-1), with d = z in the camera optical frame.
#include <gtest/gtest.h>
#include <vlo/scale/projection.h>

using namespace vlo;
using namespace vlo::scale;

TEST(Projection, PixelAndDepthOfKnownPoints)
{
	PinholeCamera cam{500, 500, 320, 240, 640, 480};
	// LiDAR 1 m left of the camera (x right in the optical frame), axes: LiDAR x forward, y left, z up.
	Eigen::Matrix3d R;
	R.col(0) = Eigen::Vector3d(0, -1, 0), R.col(1) = Eigen::Vector3d(0, 0, -1), R.col(2) = Eigen::Vector3d(1, 0, 0);
	Eigen::Isometry3d vehicle_T_camera = Eigen::Isometry3d::Identity();
	vehicle_T_camera.linear() = R;
	vehicle_T_camera.translation() = Eigen::Vector3d(0, -1, 0);
	const Eigen::Isometry3d camera_T_lidar = vehicle_T_camera.inverse();

	PointCloud scan = {{10, -1, 0, 0},  // straight ahead of the camera: the principal point, d = 10
		{10, 0, 1, 0},  // 1 m left of the camera axis, 1 m up: (320 - 50, 240 - 50)
		{20, -1, 0, 0},  //
		{-5, -1, 0, 0},  // behind
		{0.5f, -1, 0, 0},  // nearer than min_depth
		{100, -1, 0, 0},  // beyond max_depth
		{10, -7.3f, 0, 0},  // 6.3 m right at 10 m: u = 635, inside the image but in the border
		{10, -1, 4.3f, 0}};  // v = 25: kept with border 8
	const auto p = projectScan(scan, cam, camera_T_lidar, 1.0, 80.0, 8);
	ASSERT_EQ(p.size(), 4u);
	EXPECT_EQ(p[0].index, 0);
	EXPECT_NEAR(p[0].px.x, 320, 1e-4);
	EXPECT_NEAR(p[0].px.y, 240, 1e-4);
	EXPECT_NEAR(p[0].depth, 10, 1e-5);
	EXPECT_EQ(p[1].index, 1);
	EXPECT_NEAR(p[1].px.x, 270, 1e-3);
	EXPECT_NEAR(p[1].px.y, 190, 1e-3);
	EXPECT_NEAR(p[1].depth, 10, 1e-5);  // z, not the range sqrt(102)
	EXPECT_EQ(p[2].index, 2);
	EXPECT_NEAR(p[2].depth, 20, 1e-5);
	EXPECT_EQ(p[3].index, 7);
	EXPECT_NEAR(p[3].px.y, 25, 1e-3);
	// No depth limit, no border.
	EXPECT_EQ(projectScan(scan, cam, camera_T_lidar, 1.0, 0, 0).size(), 6u);
}
