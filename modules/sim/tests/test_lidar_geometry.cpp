// LiDAR ranges against exact geometry: a ground plane, a wall and a box, ray cast analytically.
#include "sim_test_util.h"

#include <gtest/gtest.h>
#include <vlo/sim/lidar_sim.h>
#include <vlo/sim/renderer.h>
#include <vlo/sim/rng.h>
#include <vlo/sim/shapes.h>
#include <vlo/sim/textures.h>
#include <vlo/sim/world.h>

#include <mrpt/opengl/COpenGLScene.h>

#include <cmath>

using namespace vlo;
using namespace vlo::sim;

namespace
{
constexpr double kPixel = 0.0025;  // rad: a LiDAR depth-view pixel is 0.8 x the azimuth step (0.14 deg)

/// Ground z = 0, a wall x = 12 (y in [-30, 30], 10 m tall), a 2 x 3 x 1.5 box at (6, -5).
World testWorld()
{
	World w;
	const int t = w.addTexture(sidewalkTexture(3));
	w.addMetricQuad(t, {-150, -150, 0}, {150, -150, 0}, {150, 150, 0}, {-150, 150, 0});
	w.addMetricQuad(t, {12, 30, 0}, {12, -30, 0}, {12, -30, 10}, {12, 30, 10});
	Eigen::Isometry3d box = Eigen::Isometry3d::Identity();
	box.translation() = Eigen::Vector3d(6, -5, 0);
	box.rotate(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
	addBox(w, box, 2, 3, 1.5, t, t);
	return w;
}

Eigen::Isometry3d lidarPose(double t)
{
	// 14 m/s forward while turning at 0.3 rad/s: 1.4 m and 1.7 deg per sweep.
	Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
	p.translation() = Eigen::Vector3d(14 * t, 0.5 * t, 1.73);
	p.linear() = (Eigen::AngleAxisd(0.3 * t + 0.05, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitY()))
					 .toRotationMatrix();
	return p;
}

struct Result
{
	std::size_t points = 0, within = 0, edge = 0, bad = 0;
	double worst = 0;
	double max_err_plane = 0;
};

/// Compares every point with the exact hit along the same beam from the pose at its firing time. A
/// point off by more than `tol` must be an edge effect and still lie on a surface.
Result check(const World& w, const LidarSim& lidar, const PointCloud& cloud, double time, bool distortion, double tol)
{
	Result r;
	for (const auto& p : cloud)
	{
		const Eigen::Vector3d pl(p.x, p.y, p.z);
		const double range = pl.norm(), phi = std::atan2(pl.y(), pl.x());
		const Eigen::Isometry3d pose = lidarPose(time + (distortion ? lidar.firingTime(phi) : 0.0));
		const Eigen::Vector3d o = pose.translation(), d = pose.linear() * pl / range;
		double truth = -1;
		const bool hit = w.raycast(o, d, 200, truth);
		++r.points;
		if (hit && std::abs(truth - range) <= tol)
		{
			++r.within;
			continue;
		}
		// Within a pixel of an edge the beam may take the neighbouring surface (or extend the nearer
		// one by up to half a pixel): the point must still lie on, or right next to, real geometry.
		if (test::nearSurface(w, o + range * d, tol + range * kPixel)) ++r.edge;
		else
			++r.bad, r.worst = std::max(r.worst, hit ? std::abs(truth - range) : 99.0);
	}
	return r;
}

PointCloud scan(const World& w, const LidarSim& lidar, double time, const LidarNoise& noise, uint64_t seed)
{
	mrpt::opengl::COpenGLScene scene;
	scene.insert(w.makeOpenGL());
	std::vector<std::pair<int, int>> tiles(lidar.viewCount(), lidar.tileSize());
	Renderer renderer(tiles);
	const LidarSim::PoseAt at = [&](double tau) { return lidarPose(time + tau); };
	const auto views = lidar.views(at);
	std::vector<RenderedView> out;
	renderer.render(scene, views, out, true);
	Rng rng(seed);
	return lidar.sample(out, views, at, w.foliage(), noise, rng);
}
}  // namespace

TEST(LidarGeometry, Hdl64RangesMatchExactPlaneAndBox)
{
	const World w = testWorld();
	const LidarSim lidar(hdl64(), false);
	const PointCloud cloud = scan(w, lidar, 0.0, {0.0, 0.0}, 1);
	const Result r = check(w, lidar, cloud, 0.0, false, 0.02);
	EXPECT_GT(r.points, 100000u);  // 64 x 2083 beams, all downward ones hit the ground
	EXPECT_GE(r.within, 0.999 * r.points) << r.edge << " edge points";
	EXPECT_LE(r.bad, r.points / 10000) << "points off every surface; worst error " << r.worst << " m";
}

TEST(LidarGeometry, Vlp16RangesMatchAndNoiseHasTheConfiguredSigma)
{
	const World w = testWorld();
	const LidarSim lidar(vlp16(), false);
	const PointCloud exact = scan(w, lidar, 0.0, {0.0, 0.0}, 1);
	const Result r = check(w, lidar, exact, 0.0, false, 0.02);
	EXPECT_GE(r.within, 0.998 * r.points);
	EXPECT_LE(r.bad, 2u) << "worst error " << r.worst << " m";
	// Same beams with 2 cm noise: the differences are N(0, 0.02).
	const PointCloud noisy = scan(w, lidar, 0.0, {0.02, 0.0}, 7);
	ASSERT_EQ(noisy.size(), exact.size());
	double sum = 0, sum2 = 0;
	for (std::size_t i = 0; i < exact.size(); ++i)
	{
		const double e = std::hypot(noisy[i].x, noisy[i].y, noisy[i].z) - std::hypot(exact[i].x, exact[i].y, exact[i].z);
		sum += e, sum2 += e * e;
	}
	const double n = static_cast<double>(exact.size()), mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
	EXPECT_NEAR(mean, 0.0, 0.001);
	EXPECT_NEAR(sd, 0.02, 0.001);
}

TEST(LidarGeometry, DistortedSweepMatchesThePoseAtEachFiringTime)
{
	const World w = testWorld();
	const LidarSim lidar(hdl64(), true);
	const PointCloud cloud = scan(w, lidar, 0.0, {0.0, 0.0}, 1);
	const Result r = check(w, lidar, cloud, 0.0, true, 0.02);
	EXPECT_GE(r.within, 0.998 * r.points) << r.edge << " edge points";
	EXPECT_LE(r.bad, r.points / 10000) << "worst error " << r.worst << " m";
	// The forward firing happens at the frame time, the sweep spans +-50 ms.
	EXPECT_NEAR(lidar.firingTime(0.0), 0.0, 1e-12);
	EXPECT_NEAR(lidar.firingTime(M_PI / 2), -0.025, 1e-12);
	EXPECT_NEAR(lidar.firingTime(-M_PI / 2), 0.025, 1e-12);
}

TEST(LidarGeometry, IdealDeskewMovesEachReturnToThePoseAtTheFrameTime)
{
	const World w = testWorld();
	const PointCloud rolling = scan(w, LidarSim(hdl64(), true), 0.0, {0.0, 0.0}, 1);
	const PointCloud ideal = scan(w, LidarSim(hdl64(), true, true), 0.0, {0.0, 0.0}, 1);
	ASSERT_EQ(ideal.size(), rolling.size());
	ASSERT_GT(ideal.size(), 100000u);
	EXPECT_TRUE(ideal.has_time && ideal.has_ring);
	double worst = 0, largest_move = 0;
	for (std::size_t i = 0; i < ideal.size(); ++i)
	{
		const auto& r = rolling[i];
		const Eigen::Vector3d p(r.x, r.y, r.z), q(ideal[i].x, ideal[i].y, ideal[i].z);
		const Eigen::Vector3d expected = lidarPose(0).inverse() * lidarPose(r.time) * p;
		worst = std::max(worst, (q - expected).norm());
		largest_move = std::max(largest_move, (q - p).norm());
		EXPECT_EQ(ideal[i].time, 0.0f);
		EXPECT_EQ(ideal[i].ring, r.ring);
	}
	EXPECT_LT(worst, 1e-4);  // float coordinates
	EXPECT_GT(largest_move, 0.5);  // the sweep spans 1.4 m of motion
}
