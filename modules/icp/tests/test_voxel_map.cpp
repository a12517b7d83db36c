// The voxel map's bounds: points per voxel, their spacing, the radius, and the 27-voxel search.
#include <gtest/gtest.h>
#include <vlo/icp/preprocessing.h>
#include <vlo/icp/voxel_map.h>

#include <random>

#include "scene.h"

namespace vlo::icp::test
{
TEST(VoxelMap, AVoxelKeepsAtMostMaxPointsSpreadApart)
{
	VoxelMap map(1.0, 20, 100.0);
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	Points cube;
	for (int i = 0; i < 5000; ++i) cube.emplace_back(2 + u(rng), 3 + u(rng), 4 + u(rng));
	map.addPoints(cube);
	EXPECT_EQ(map.voxelCount(), 1u);
	EXPECT_EQ(map.pointCount(), 20u);
	const Points kept = map.points();
	for (std::size_t i = 0; i < kept.size(); ++i)
		for (std::size_t j = i + 1; j < kept.size(); ++j)
			EXPECT_GE((kept[i] - kept[j]).norm(), std::sqrt(1.0 / 20));
}

TEST(VoxelMap, DropsVoxelsBeyondTheRadius)
{
	VoxelMap map(1.0, 20, 50.0);
	map.addPoints({{10.5, 0.5, 0.5}, {49.2, 0.5, 0.5}, {60.5, 0.5, 0.5}, {-70.5, 0.5, 0.5}});
	EXPECT_EQ(map.voxelCount(), 4u);
	map.removeFarFrom(Eigen::Vector3d::Zero());
	EXPECT_EQ(map.voxelCount(), 2u);
	// update() adds in the map frame and drops around the new sensor position.
	map.update({{0.0, 0.0, 0.0}}, motion(40, 0, 0, 0));
	EXPECT_EQ(map.voxelCount(), 3u);  // 10.5 is 29.5 m from x = 40: kept
	map.update({}, motion(100, 0, 0, 0));
	EXPECT_EQ(map.voxelCount(), 0u);
}

TEST(VoxelMap, NearestSearchesTheNeighbouringVoxelsOnly)
{
	VoxelMap map(1.0, 20, 100.0);
	map.addPoints({{0.9, 0.5, 0.5}, {2.5, 0.5, 0.5}});
	Eigen::Vector3d q;
	double d2 = 0;
	ASSERT_TRUE(map.nearest({1.05, 0.5, 0.5}, q, d2));  // across the voxel border
	EXPECT_TRUE(q.isApprox(Eigen::Vector3d(0.9, 0.5, 0.5)));
	EXPECT_NEAR(d2, 0.15 * 0.15, 1e-12);
	EXPECT_FALSE(map.nearest({4.5, 0.5, 0.5}, q, d2));  // two voxels away from both
	EXPECT_FALSE(map.nearest({1.05, 0.5, 0.5}, q, d2, 0.1 * 0.1));  // beyond the gate
	// A closer point in a neighbour voxel wins over one in the query's own voxel.
	map.addPoints({{1.9, 0.5, 0.5}});
	ASSERT_TRUE(map.nearest({2.05, 0.5, 0.5}, q, d2));
	EXPECT_TRUE(q.isApprox(Eigen::Vector3d(1.9, 0.5, 0.5)));
}

TEST(Preprocessing, CropAndDownsample)
{
	const Points in{{0.5, 0, 0}, {5, 0, 0}, {5.1, 0.1, 0}, {150, 0, 0}, {std::nan(""), 0, 0}, {0, 7, 0}};
	const Points cropped = cropRange(in, 1.0, 100.0);
	ASSERT_EQ(cropped.size(), 3u);
	const Points down = voxelDownsample(cropped, 1.0);
	ASSERT_EQ(down.size(), 2u);  // 5.0 and 5.1 share a voxel: the first is kept
	EXPECT_EQ(down[0].x(), 5.0);
	EXPECT_EQ(down[1].y(), 7.0);
}
}  // namespace vlo::icp::test
