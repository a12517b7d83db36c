#include <gtest/gtest.h>
#include <vlo/pipeline/global_map.h>

using namespace vlo;

TEST(GlobalMap, OnePointPerVoxelInWorldFrame)
{
	GlobalMap map(0.5, 50.0);
	PointCloud scan{{0.1f, 0.1f, 0.1f, 1}, {0.2f, 0.2f, 0.2f, 2}, {1.1f, 0.1f, 0.1f, 3}, {80.f, 0, 0, 4}};
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
	pose.translation() = Eigen::Vector3d(10, 0, 0);
	map.insert(scan, pose);
	ASSERT_EQ(map.points().size(), 2u);  // two share a voxel, one is beyond max_range
	EXPECT_NEAR(map.points()[0].x, 10.1f, 1e-5);
	EXPECT_NEAR(map.points()[1].x, 11.1f, 1e-5);
	map.insert(scan, pose);  // the same place again adds nothing
	EXPECT_EQ(map.points().size(), 2u);
}
