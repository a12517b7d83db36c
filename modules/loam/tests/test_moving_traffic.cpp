// Moving things (doc/LOAM.md "Moving things"): the free space a scan sees, and a drive past a
// convoy of vans whose points would match their own earlier surfaces in the map and pull the
// registration along the convoy's motion.
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
constexpr double kEgoStep = 1.0;  ///< ego motion per frame [m] (10 m/s)
constexpr double kVanStep = 0.6;  ///< the vans' motion per frame [m]: within the map's neighbour radius
constexpr int kFrames = 60;

/// The vans at frame i: a convoy in the lane to the ego's left, driving ahead of it in its direction
/// (they fall behind, so the ego passes all of them), 8 m apart.
std::vector<Box> convoy(const Path& path, int i)
{
	std::vector<Box> vans;
	for (int k = 0; k < 8; ++k)
	{
		const double s = 6 + 8 * k + kVanStep * i;
		const Eigen::Isometry3d P = path.at(s);
		const double yaw = std::atan2(P.linear()(1, 0), P.linear()(0, 0));
		vans.push_back(Box{P.translation() + 2.4 * P.linear().col(1) + Eigen::Vector3d(0, 0, 1.15), Eigen::Vector3d(2.6, 1.0, 1.15), yaw});
	}
	return vans;
}

/// Final translation error of LOAM alone over the drive [m].
double finalError(const LidarModel& lidar, const LoamOptions& o)
{
	Path path;
	path.add(120, 0.0);
	const World still = urbanWorld(path, 3);
	std::mt19937 rng(3);
	LidarOdometry lo(o);
	const Eigen::Isometry3d T0 = lidarPoseAt(path, 0);
	double err = 0;
	for (int i = 0; i < kFrames; ++i)
	{
		World w = still;
		for (const Box& b : convoy(path, i)) w.boxes.push_back(b);
		const Eigen::Isometry3d truth = lidarPoseAt(path, kEgoStep * i);
		const LidarOdometryResult r = lo.process(0.1 * i, scan(w, lidar, truth, &rng), std::nullopt);
		err = translationError(r.pose, T0.inverse() * truth);
	}
	return err;
}

void expectConvoyIgnored(LidarModel lidar, LoamOptions o, const char* name)
{
	lidar.noise_sigma = 0.01;
	const double with = finalError(lidar, o);
	o.mapping.free_space_radius = 0;
	const double without = finalError(lidar, o);
	const double length = kEgoStep * (kFrames - 1);
	std::printf("%s past a convoy, %.0f m: final error %.3f m with free space, %.3f m without\n", name, length, with, without);
	EXPECT_LT(with, 0.002 * length);
	EXPECT_GT(without, 0.002 * length);
}

ScanPoints scanPoints(const PointCloud& pc)
{
	ScanPoints out;
	for (const LidarPoint& p : pc) out.push_back(ScanPoint{Eigen::Vector3f(p.x, p.y, p.z), 0.0f, p.ring});
	return out;
}
}  // namespace

TEST(MovingTraffic, Hdl64ConvoyDoesNotPullTheRegistration) { expectConvoyIgnored(hdl64(), hdl64Options(), "HDL-64"); }

TEST(MovingTraffic, Vlp16ConvoyDoesNotPullTheRegistration) { expectConvoyIgnored(vlp16(), vlp16Options(), "VLP-16"); }

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
