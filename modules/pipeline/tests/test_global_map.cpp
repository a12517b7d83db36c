#include <gtest/gtest.h>
#include <vlo/pipeline/global_map.h>

#include <cmath>
#include <unordered_set>

using namespace vlo;
using namespace vlo::pipeline;

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

TEST(GlobalMap, TakePointsHandsTheMapOver)
{
	GlobalMap map(0.5, 50.0);
	PointCloud scan{{0.1f, 0.1f, 0.1f, 1}, {1.1f, 0.1f, 0.1f, 3}};
	map.insert(scan, Eigen::Isometry3d::Identity());
	const PointCloud kept = map.points();
	const PointCloud taken = map.takePoints();
	ASSERT_EQ(taken.size(), 2u);
	EXPECT_EQ(taken[1].x, kept[1].x);
	EXPECT_TRUE(map.points().empty());
	map.insert(scan, Eigen::Isometry3d::Identity());  // its voxel index went with them: usable again
	EXPECT_EQ(map.points().size(), 2u);
}

// A synthetic drive of 50 km: a street of 20 m between walls, scanned every 20 m. The map keeps its budget
// of points (memory does not grow with the drive's length) by coarsening its voxels, each time by 2.
TEST(GlobalMap, LongDriveStaysWithinItsBudget)
{
	PointCloud scan;  // walls at y = +-10 m and the ground, 40 m ahead and behind: ~12k points
	for (float x = -40; x <= 40; x += 0.2f)
		for (float z = -1.7f; z <= 3.0f; z += 0.5f)
		{
			scan.push_back({x, 10.0f, z, 1});
			scan.push_back({x, -10.0f, z, 1});
			scan.push_back({x, 0.3f * z, -1.73f, 1});
		}
	const std::size_t budget = 200'000;
	GlobalMap map(0.2, 60.0, budget);
	GlobalMap unbounded(0.2, 60.0, 1u << 30);
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
	std::size_t most = 0;
	for (int k = 0; k < 2'500; ++k)
	{
		pose.translation().x() = 20.0 * k;
		map.insert(scan, pose);
		most = std::max(most, map.points().size());
		if (k < 250) unbounded.insert(scan, pose);
	}
	EXPECT_LE(most, budget);
	EXPECT_GT(map.points().size(), budget / 4);  // coarsening by 2 keeps over a quarter
	// 5 km unbounded hold more than twice the budget: without it the 50 km map would be ~10x that.
	EXPECT_GT(unbounded.points().size(), 2 * budget);
	EXPECT_NEAR(unbounded.leaf(), 0.2, 1e-12);
	const double leaf = map.leaf();
	EXPECT_GE(leaf, 0.8);
	EXPECT_NEAR(std::log2(leaf / 0.2), std::round(std::log2(leaf / 0.2)), 1e-9);
	// One point per voxel of the final size, spread over the whole drive.
	std::unordered_set<long long> voxels;
	float far = 0;
	for (const auto& p : map.points())
	{
		const auto c = [&](float v) { return static_cast<long long>(std::floor(v / static_cast<float>(leaf))); };
		EXPECT_TRUE(voxels.insert((c(p.x) * 1000003LL + c(p.y)) * 1000003LL + c(p.z)).second);
		far = std::max(far, p.x);
	}
	EXPECT_GT(far, 49'900.f);
}
