// Moving things (doc/LOAM.md "Moving things"): the free space a scan sees, and the trail of ghosts
// a van driving past leaves in the map without it.
#include <gtest/gtest.h>
#include <vlo/loam/free_space.h>
#include <vlo/loam/lidar_odometry.h>
#include <vlo/loam/near_points.h>

#include <cstdio>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
/// A parked ego vehicle at x = 40 of a street; a van drives past it in the lane to its left, from
/// x = 22 to x = 58 at 1 m per frame. Returns how many map points are left, after it has gone, where
/// the van was (its swept volume short of where it stands last, above the ground).
std::size_t ghostPoints(LidarModel lidar, const LoamOptions& o)
{
	lidar.noise_sigma = 0.01;
	Path path;
	path.add(80, 0.0);
	const World street = urbanWorld(path, 5);
	std::mt19937 rng(5);
	LidarOdometry lo(o);
	const Eigen::Isometry3d ego = lidarPoseAt(path, 40);
	const Eigen::Vector3d half(2.6, 1.0, 1.15);
	for (int i = 0; i <= 36; ++i)
	{
		World w = street;
		w.boxes.push_back(Box{Eigen::Vector3d(22 + i, 2.5, half.z()), half, 0.0});
		lo.process(0.1 * i, scan(w, lidar, ego, &rng), std::nullopt);
	}
	std::size_t n = 0;
	for (const Eigen::Vector3f& p : lo.mapPoints())  // ego at the map origin: map x = world x - 40
		if (p.x() > 22 - 40 && p.x() < 58 - half.x() - 0.5 - 40 && p.y() > 1.3f && p.y() < 3.4f && p.z() > 0.4f - 1.73f &&
			p.z() < 2.2f - 1.73f)
			++n;
	return n;
}

void expectGhostsCarved(const LidarModel& lidar, LoamOptions o, const char* name)
{
	const std::size_t with = ghostPoints(lidar, o);
	o.mapping.free_space_radius = 0;
	const std::size_t without = ghostPoints(lidar, o);
	std::printf("%s: %zu map points left where a van drove by with free space, %zu without\n", name, with, without);
	EXPECT_GT(without, 100u);
	EXPECT_LT(with, without / 2);  // measured: a quarter (HDL-64) and a third (VLP-16): ghosts no later beam passed stay
}

ScanPoints scanPoints(const PointCloud& pc)
{
	ScanPoints out;
	for (const LidarPoint& p : pc) out.push_back(ScanPoint{Eigen::Vector3f(p.x, p.y, p.z), 0.0f, p.ring});
	return out;
}
}  // namespace

TEST(MovingTraffic, Hdl64GhostsOfAPassingVanAreCarved) { expectGhostsCarved(hdl64(), hdl64Options(), "HDL-64"); }

TEST(MovingTraffic, Vlp16GhostsOfAPassingVanAreCarved) { expectGhostsCarved(vlp16(), vlp16Options(), "VLP-16"); }

TEST(MovingTraffic, FreeSpaceIsWhereBeamsPassedAndTheGroundIsNot)
{
	// A VLP-16 1.73 m above flat ground, facing a wall 25 m ahead.
	World w;
	w.boxes.push_back(Box{Eigen::Vector3d(26, 0, 5), Eigen::Vector3d(1, 40, 5), 0.0});
	const Eigen::Isometry3d pose(Eigen::Translation3d(0, 0, 1.73));
	const ScanPoints pts = scanPoints(scan(w, vlp16(), pose));
	const FreeSpace free(pts, 900);
	const auto through = [&](const Eigen::Vector3f& q) { return free.seenThrough(q, 0.1f, 0.5f, 0.1f); };
	int on_wall = 0;
	for (const ScanPoint& sp : pts)
	{
		if (sp.p.x() < 24.9f || std::abs(sp.p.y()) > 5) continue;
		++on_wall;
		const Eigen::Vector3f d = sp.p.normalized();
		EXPECT_TRUE(through(12.0f * d)) << "a point half way along a beam";
		EXPECT_FALSE(through(12.0f * d + Eigen::Vector3f(0, 0, 0.2f))) << "between two beams";
		EXPECT_FALSE(through(sp.p - 2.5f * d)) << "within the margin of the return";
	}
	EXPECT_GT(on_wall, 100);
	// The ground, however grazing the beams: a ground point within a beam's radius is never
	// before its return by more than the range-proportional margin.
	for (float x = 4; x < 24; x += 0.05f)
		for (float y : {-2.0f, -0.7f, 0.0f, 0.3f, 1.9f}) EXPECT_FALSE(through(Eigen::Vector3f(x, y, -1.73f))) << x << " " << y;
}
TEST(MovingTraffic, NearPointsWithinTheRadiusOnly)
{
	const NearPoints near({Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(10, 0, 0)}, 1.0f);
	EXPECT_TRUE(near.near(Eigen::Vector3f(0.99f, 0, 0)));
	EXPECT_TRUE(near.near(Eigen::Vector3f(9.5f, 0.5f, -0.5f)));
	EXPECT_FALSE(near.near(Eigen::Vector3f(0.8f, 0.8f, 0)));  // 1.13 m away, in a neighbouring cell
	EXPECT_FALSE(near.near(Eigen::Vector3f(5, 0, 0)));
	EXPECT_TRUE(NearPoints({}, 1.0f).empty());
}
}  // namespace vlo::loam::test
