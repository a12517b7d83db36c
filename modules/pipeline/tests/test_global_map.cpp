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

// Two visits of one wall, the second seen from a pose 0.8 m off (drift): corrected with the second
// scan's correction, the two copies fall into the same voxels and one is kept.
TEST(GlobalMap, CorrectMovesEachScanByItsAnchorAndThinsAgain)
{
	PointCloud wall;
	for (int i = 0; i < 20; ++i) wall.push_back({static_cast<float>(i) * 0.5f + 0.25f, 5.25f, 0.25f, 1});
	GlobalMap map(0.5, 50.0);
	map.insert(wall, Eigen::Isometry3d::Identity(), 0);
	Eigen::Isometry3d drifted = Eigen::Isometry3d::Identity();
	drifted.translation() = Eigen::Vector3d(0, 0.8, 0);  // where the odometry thinks the second visit was
	map.insert(wall, drifted, 1);
	ASSERT_EQ(map.points().size(), 40u);  // two copies of the wall, 0.8 m apart
	map.correct({Eigen::Isometry3d::Identity(), drifted.inverse()});
	ASSERT_EQ(map.points().size(), 20u);
	for (std::size_t i = 0; i < 20; ++i)
	{
		EXPECT_NEAR(map.points()[i].x, wall[i].x, 1e-5);
		EXPECT_NEAR(map.points()[i].y, 5.25, 1e-5);
	}
	EXPECT_THROW(map.correct({}), std::out_of_range);  // a correction for each anchor, or none
}

TEST(GlobalMap, CorrectByIdentityKeepsTheMapAsItWas)
{
	GlobalMap map(0.2, 60.0);
	PointCloud scan;
	for (int i = 0; i < 500; ++i)
		scan.push_back({std::sin(0.1f * i) * 20, std::cos(0.13f * i) * 20, 0.01f * static_cast<float>(i % 50), 1});
	for (std::uint32_t k = 0; k < 3; ++k)
	{
		Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
		pose.translation() = Eigen::Vector3d(1.3 * k, 0.1 * k, 0);
		map.insert(scan, pose, k);
	}
	const PointCloud before = map.points();
	map.correct(std::vector<Eigen::Isometry3d>(3, Eigen::Isometry3d::Identity()));
	ASSERT_EQ(map.points().size(), before.size());
	for (std::size_t i = 0; i < before.size(); ++i)
		EXPECT_TRUE(map.points()[i].x == before[i].x && map.points()[i].y == before[i].y && map.points()[i].z == before[i].z);
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
