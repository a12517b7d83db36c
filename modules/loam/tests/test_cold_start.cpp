// A cold start at speed: with no prior at all (constant velocity starting from zero) the first
// motion of a vehicle already driving at up to 35 m/s (3.5 m per 10 Hz frame) is recovered, in any
// direction, and so is the motion after a gap of several frames.
#include <gtest/gtest.h>
#include <vlo/loam/cold_start.h>
#include <vlo/loam/lidar_odometry.h>

#include <cmath>
#include <cstdio>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
Path straight()
{
	Path p;
	p.add(120, 0.0);
	return p;
}

// Two scans, the second moved by `delta` (in the first one's frame), registered from a zero prior.
LidarOdometryResult registerPair(bool hdl, const Eigen::Isometry3d& delta, unsigned seed)
{
	const Path path = straight();
	const World w = urbanWorld(path, seed);
	LidarModel m = hdl ? hdl64() : vlp16();
	m.noise_sigma = 0.01;
	std::mt19937 rng(seed);
	const Eigen::Isometry3d A = lidarPoseAt(path, 50);
	LidarOdometry lo(hdl ? hdl64Options() : vlp16Options());
	lo.process(0.0, scan(w, m, A, &rng), std::nullopt);
	const LidarOdometryResult r = lo.process(0.1, scan(w, m, A * delta, &rng), std::nullopt);
	std::printf("%s from zero to (%.1f, %.1f m, %.0f deg): error %.4f m, %.4f deg; scan-to-scan %d rounds, %.4f m\n",
		hdl ? "HDL-64" : "VLP-16", delta.translation().x(), delta.translation().y(),
		rotationAngle(delta.linear()) * 180 / M_PI, translationError(r.pose, delta), rotationErrorDeg(r.pose, delta),
		r.odometry.rounds, translationError(r.odometry.T_prev_curr, delta));
	return r;
}

void expectColdStart(bool hdl)
{
	// Forward and backward at 35 m/s, and sideways/diagonal with a turn: nothing assumes x.
	const Eigen::Isometry3d deltas[] = {planarPose(3.5, 0, 0), planarPose(-3.5, 0, 0), planarPose(0.3, 3.5, 3), planarPose(-2.4, -2.4, -8)};
	unsigned seed = 60;
	for (const Eigen::Isometry3d& d : deltas)
	{
		const LidarOdometryResult r = registerPair(hdl, d, seed++);
		EXPECT_EQ(r.status, LidarFrameStatus::Ok) << r.reason;
		EXPECT_LT(translationError(r.pose, d), 0.02);
		EXPECT_LT(rotationErrorDeg(r.pose, d), 0.1);
	}
}
}  // namespace

TEST(ColdStart, Hdl64RecoversThreeAndAHalfMetresFromZero) { expectColdStart(true); }

TEST(ColdStart, Vlp16RecoversThreeAndAHalfMetresFromZero) { expectColdStart(false); }

// A drive at 30 m/s from the first frame, with frames 8-10 missing (a gap of 0.4 s, 12 m), the
// other way round as well: every pose within 1 % of the distance driven.
TEST(ColdStart, DriveAtThirtyMetresPerSecondWithAGap)
{
	const Path path = straight();
	const World w = urbanWorld(path, 21);
	LidarModel m = hdl64();
	m.noise_sigma = 0.01;
	for (const double dir : {1.0, -1.0})
	{
		std::mt19937 rng(21);
		LidarOdometry lo(hdl64Options());
		const double s0 = dir > 0 ? 20.0 : 100.0;
		const Eigen::Isometry3d T0 = lidarPoseAt(path, s0);
		double max_rel = 0;
		for (int i = 0; i < 20; ++i)
		{
			if (i >= 8 && i <= 10) continue;
			const Eigen::Isometry3d truth = T0.inverse() * lidarPoseAt(path, s0 + dir * 3.0 * i);
			const LidarOdometryResult r = lo.process(0.1 * i, scan(w, m, T0 * truth, &rng), std::nullopt);
			EXPECT_EQ(r.status, i ? LidarFrameStatus::Ok : LidarFrameStatus::Initialized) << i << ": " << r.reason;
			if (i > 0) max_rel = std::max(max_rel, translationError(r.pose, truth) / (3.0 * i));
		}
		std::printf("30 m/s %s with a 0.4 s gap: largest error %.3f %% of the distance\n", dir > 0 ? "forward" : "backward",
			100 * max_rel);
		EXPECT_LT(max_rel, 0.01);
	}
}
}  // namespace vlo::loam::test

namespace vlo::loam::test
{
TEST(ColdStart, InliersAreTheMatchesWithinTheDistance)
{
	// A plane z = 0 and a line along x through (0, 2, 0): moved 5 cm up, the point on the plane
	// stays within 0.1 m, one moved 0.3 m off the line does not.
	Matches m;
	m.planes.push_back(PlaneMatch{Eigen::Vector3d(3, 0, 0), Eigen::Vector3d::UnitZ(), 0.0});
	m.edges.push_back(EdgeMatch{Eigen::Vector3d(1, 2.3, 0), Eigen::Vector3d(0, 2, 0), Eigen::Vector3d::UnitX()});
	m.edges.push_back(EdgeMatch{Eigen::Vector3d(7, 2.05, 0), Eigen::Vector3d(0, 2, 0), Eigen::Vector3d::UnitX()});
	Eigen::Isometry3d up = Eigen::Isometry3d::Identity();
	up.translation().z() = 0.05;
	EXPECT_EQ(countInliers(m, up, 0.1), 2);  // the plane point and the second edge point (7 cm off)
	EXPECT_EQ(countInliers(m, up, 0.04), 0);
	EXPECT_EQ(countInliers(m, up, 0.4), 3);
}

TEST(ColdStart, InliersAlongTheWayAreThoseThatFixIt)
{
	// At the identity: the ground (normal z), a wall along the road (normal y), a curb (a line along
	// x), a pole (a vertical line) and a wall across the road (normal x, 30 deg off), all fit. Along x
	// only the pole (1) and the wall across (cos^2 30 deg) fix the translation; along y the wall along
	// the road, the curb and the pole (1 each) and the wall across (sin^2 30 deg).
	Matches m;
	m.planes.push_back(PlaneMatch{Eigen::Vector3d(3, 0, -1.7), Eigen::Vector3d::UnitZ(), 1.7});
	m.planes.push_back(PlaneMatch{Eigen::Vector3d(3, 8, 1), Eigen::Vector3d::UnitY(), -8});
	const Eigen::Vector3d across(std::cos(M_PI / 6), std::sin(M_PI / 6), 0);
	m.planes.push_back(PlaneMatch{20 * across, across, -20});
	m.edges.push_back(EdgeMatch{Eigen::Vector3d(2, -4, -1.6), Eigen::Vector3d(0, -4, -1.6), Eigen::Vector3d::UnitX()});
	m.edges.push_back(EdgeMatch{Eigen::Vector3d(6, -5, 0.5), Eigen::Vector3d(6, -5, 0), Eigen::Vector3d::UnitZ()});
	const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
	EXPECT_EQ(countInliers(m, I, 0.1), 5);
	EXPECT_NEAR(inliersAlong(m, I, 0.1, Eigen::Vector3d::UnitX()), 1 + 0.75, 1e-12);
	EXPECT_NEAR(inliersAlong(m, I, 0.1, Eigen::Vector3d::UnitY()), 3 + 0.25, 1e-12);
	Eigen::Isometry3d ahead = I;
	ahead.translation().x() = 0.5;  // the pole and the wall across no longer fit
	EXPECT_EQ(countInliers(m, ahead, 0.1), 3);
	EXPECT_NEAR(inliersAlong(m, ahead, 0.1, Eigen::Vector3d::UnitX()), 0, 1e-12);
}

TEST(ColdStart, FirstMotionSearchKeepsTheHypothesisThatFitsBest)
{
	// 2.6 m forward: the search tries 17 starts (zero, and 0.75-3 m along +-x, +-y) and keeps the
	// result that fits most features, the true motion.
	const Path path = straight();
	const World w = urbanWorld(path, 70);
	LidarModel m = hdl64();
	m.noise_sigma = 0.01;
	std::mt19937 rng(70);
	const LoamOptions o = hdl64Options();
	ScanFeatureExtractor fx(o);
	ScanToScanOdometry odo(o.odometry, fx.model());
	const Eigen::Isometry3d A = lidarPoseAt(path, 50), delta = planarPose(2.6, 0.1, 1);
	odo.setReference(fx.extract(scan(w, m, A, &rng)).features);
	const ColdStart cs = searchFirstMotion(odo, fx.extract(scan(w, m, A * delta, &rng)).features, 3.0, 0.75);
	EXPECT_EQ(cs.hypotheses, 17);
	EXPECT_LT(translationError(cs.motion, delta), 0.02);
	EXPECT_GT(cs.inliers, 500);
}
}  // namespace vlo::loam::test
