// Feature extraction on synthetic scans with known edges and planes.
#include <gtest/gtest.h>
#include <vlo/loam/features.h>
#include <vlo/loam/rings.h>

#include <cmath>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
// A 20 m x 12 m room with 4 m walls and no ceiling: four walls (thin boxes) on the ground, the sensor 1.5 m up.
constexpr double kHx = 10, kHy = 6;
World boxRoom()
{
	World w;
	w.boxes.push_back(Box{Eigen::Vector3d(kHx + 0.25, 0, 2), Eigen::Vector3d(0.25, kHy + 0.5, 2), 0});
	w.boxes.push_back(Box{Eigen::Vector3d(-kHx - 0.25, 0, 2), Eigen::Vector3d(0.25, kHy + 0.5, 2), 0});
	w.boxes.push_back(Box{Eigen::Vector3d(0, kHy + 0.25, 2), Eigen::Vector3d(kHx + 0.5, 0.25, 2), 0});
	w.boxes.push_back(Box{Eigen::Vector3d(0, -kHy - 0.25, 2), Eigen::Vector3d(kHx + 0.5, 0.25, 2), 0});
	return w;
}

Eigen::Isometry3d sensorPose()
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation() = Eigen::Vector3d(1.0, 0.5, 1.5);
	return T;
}

constexpr double kHeight = 4;

double distanceToCorner(const Eigen::Vector3d& w)
{
	double d = 1e9;
	for (double sx : {-kHx, kHx})
		for (double sy : {-kHy, kHy}) d = std::min(d, std::hypot(w.x() - sx, w.y() - sy));
	return d;
}

// Distance (in the world) to the nearest of the room's edges: the 4 vertical corners, the 4
// wall-floor junctions and the 4 wall tops.
double distanceToRoomEdge(const Eigen::Vector3d& w)
{
	double d = distanceToCorner(w);
	for (double z : {0.0, kHeight})
	{
		for (double sx : {-kHx, kHx}) d = std::min(d, std::hypot(w.x() - sx, w.z() - z));
		for (double sy : {-kHy, kHy}) d = std::min(d, std::hypot(w.y() - sy, w.z() - z));
	}
	return d;
}

double distanceToRoomSurface(const Eigen::Vector3d& w)
{
	return std::min({std::abs(std::abs(w.x()) - kHx), std::abs(std::abs(w.y()) - kHy), std::abs(w.z())});
}
}  // namespace

TEST(Features, StraightRingHasZeroCurvature)
{
	RingScan rs;
	rs.ring_begin = {0, 200};
	for (int i = 0; i < 200; ++i)
	{
		ScanPoint p;
		p.p = Eigen::Vector3f(10.0f, -10.0f + 0.1f * i, -1.0f);
		p.time = i / 200.0f;
		rs.points.push_back(p);
	}
	FeatureExtractor fx(FeatureOptions{});
	const FeatureSet f = fx.extract(rs);
	for (int i = 5; i < 195; ++i) EXPECT_NEAR(fx.lastCurvatures()[i], 0.0f, 1e-6);
	EXPECT_TRUE(f.sharp.empty());
	EXPECT_GE(f.flat.size(), 6u * 4u - 2u);  // suppression across sector borders may cost one
	EXPECT_LE(f.flat.size(), 6u * 4u);
	EXPECT_FALSE(f.less_flat.empty());
	for (std::size_t i = 1; i < f.less_flat.size(); ++i)
		EXPECT_GE((f.less_flat[i].p - f.less_flat[i - 1].p).norm(), 0.1f);  // downsampled at 0.2 m
}

TEST(Features, BoxRoomCornersAreEdgesWallsArePlanes)
{
	const World room = boxRoom();
	const Eigen::Isometry3d T = sensorPose();
	const LoamOptions o = vlp16Options();
	ScanPreprocessor pre(o.scan);
	FeatureExtractor fx(o.features);
	const FeatureSet f = fx.extract(pre.process(scan(room, vlp16(), T)));

	ASSERT_GT(f.sharp.size(), 8u);
	EXPECT_LE(f.sharp.size(), 16u * 6u * 2u);
	EXPECT_LE(f.less_sharp.size(), 16u * 6u * 20u);
	EXPECT_LE(f.flat.size(), 16u * 6u * 4u);
	EXPECT_GE(f.flat.size(), 16u * 6u * 3u);
	EXPECT_GE(f.less_sharp.size(), f.sharp.size());

	int corners_seen[4] = {0, 0, 0, 0};
	for (const ScanPoint& p : f.sharp)
	{
		const Eigen::Vector3d w = T * p.p.cast<double>();
		EXPECT_LT(distanceToRoomEdge(w), 0.3) << w.transpose();
		const int c = (w.x() > 0 ? 1 : 0) + (w.y() > 0 ? 2 : 0);
		if (std::hypot(std::abs(w.x()) - kHx, std::abs(w.y()) - kHy) < 0.3) ++corners_seen[c];
	}
	for (int c = 0; c < 4; ++c) EXPECT_GT(corners_seen[c], 0) << "corner " << c;

	for (const ScanPoint& p : f.flat)
	{
		const Eigen::Vector3d w = T * p.p.cast<double>();
		EXPECT_LT(distanceToRoomSurface(w), 0.01) << w.transpose();
		EXPECT_GT(distanceToCorner(w), 0.2) << w.transpose();
	}
	for (const ScanPoint& p : f.less_flat) EXPECT_LT(distanceToRoomSurface(T * p.p.cast<double>()), 0.05);
}

TEST(Features, OccludedSideOfADepthJumpIsNeverAnEdge)
{
	// A pole 4 m in front of the sensor, 5 m before the +x wall: the wall points next to the
	// pole's silhouette have a high curvature, but may vanish behind the pole after a small motion.
	World room = boxRoom();
	room.cylinders.push_back(Cylinder{Eigen::Vector2d(5.0, 0.5), 0.15, 0.0, 4.0});
	const Eigen::Isometry3d T = sensorPose();
	const PointCloud pc = scan(room, vlp16(), T);
	const auto sharpOnWallNearPole = [&](bool reject) {
		LoamOptions o = vlp16Options();
		o.features.reject_occluded = reject;
		ScanPreprocessor pre(o.scan);
		FeatureExtractor fx(o.features);
		int n = 0;
		for (const ScanPoint& p : fx.extract(pre.process(pc)).less_sharp)
		{
			const Eigen::Vector3d w = T * p.p.cast<double>();
			n += (std::abs(w.x() - kHx) < 0.05 && std::abs(w.y() - 0.5) < 2.5) ? 1 : 0;
		}
		return n;
	};
	EXPECT_EQ(sharpOnWallNearPole(true), 0);
	EXPECT_GT(sharpOnWallNearPole(false), 0);
}

TEST(Features, EdgesOnAPolesOutlineAreSilhouettesTheRoomsCornersCreases)
{
	// The pole's outline against the wall 5 m behind moves round the pole as the sensor moves; the
	// room's corners (both walls seen, no jump in range) are fixed lines. Occluded points and every
	// point above the threshold (not only the peaks, which here are the wall's) are kept, so both
	// sides of the jump give edges: the wall's are its far side, no silhouette.
	World room = boxRoom();
	room.cylinders.push_back(Cylinder{Eigen::Vector2d(5.0, 0.5), 0.15, 0.0, 4.0});
	const Eigen::Isometry3d T = sensorPose();
	LoamOptions o = vlp16Options();
	o.features.reject_occluded = false;
	o.features.sharp_local_max = false;
	ScanPreprocessor pre(o.scan);
	FeatureExtractor fx(o.features);
	const FeatureSet f = fx.extract(pre.process(scan(room, vlp16(), T)));
	ASSERT_EQ(f.less_sharp_silhouette.size(), f.less_sharp.size());
	int on_pole = 0, on_wall_behind = 0, at_corner = 0;
	for (std::size_t i = 0; i < f.less_sharp.size(); ++i)
	{
		const Eigen::Vector3d w = T * f.less_sharp[i].p.cast<double>();
		const int flag = f.less_sharp_silhouette[i];
		if (std::hypot(w.x() - 5.0, w.y() - 0.5) < 0.3)
		{
			++on_pole;
			EXPECT_EQ(flag, 1) << w.transpose();
		}
		if (std::abs(w.x() - kHx) < 0.05 && std::abs(w.y() - 0.5) < 2.5)
		{
			++on_wall_behind;
			EXPECT_EQ(flag, 0) << w.transpose();
		}
		if (distanceToCorner(w) < 0.3)
		{
			++at_corner;
			EXPECT_EQ(flag, 0) << w.transpose();
		}
	}
	EXPECT_GT(on_pole, 8);
	EXPECT_GT(on_wall_behind, 8);
	EXPECT_GT(at_corner, 8);
}

namespace
{
// One ring on a round wall 10 m away, a return every 0.2 deg, but none in [90, 100) deg: the
// shadow of something that returns nothing (or the sky). Azimuths [rad] of the last return before
// the gap and the first after it.
constexpr float kStep = 0.2f * 3.14159265f / 180.0f;
constexpr float kGapFirst = 89.8f * 3.14159265f / 180.0f, kGapLast = 100.0f * 3.14159265f / 180.0f;
RingScan roundWallWithGap()
{
	RingScan rs;
	for (int k = 0; k < 1800; ++k)
	{
		const float az = k * kStep;
		if (az > kGapFirst + 0.5f * kStep && az < kGapLast - 0.5f * kStep) continue;
		ScanPoint p;
		p.p = Eigen::Vector3f(10.0f * std::cos(az), 10.0f * std::sin(az), -1.0f);
		p.time = k / 1800.0f;
		rs.points.push_back(p);
	}
	rs.ring_begin = {0, rs.points.size()};
	return rs;
}

// Steps of kStep from the nearest border of the gap, on the side where the point lies.
float stepsFromGap(const ScanPoint& p)
{
	const float az = std::atan2(p.p.y(), p.p.x());
	return std::min(std::abs(az - kGapFirst), std::abs(az - kGapLast)) / kStep;
}
}  // namespace

TEST(Features, PointsBesideMissingReturnsAreNoFeatures)
{
	// A window of 5 + 5 neighbours across the 10 deg gap sums points ~1.7 m apart: the borders
	// look like edges although the wall is smooth (curvature of a uniform 10 m circle: ~5e-5 m^2).
	FeatureOptions o;
	o.max_azimuth_gap = 0;
	FeatureExtractor blind(o);
	const RingScan rs = roundWallWithGap();
	const FeatureSet f0 = blind.extract(rs);
	ASSERT_FALSE(f0.sharp.empty());
	for (const ScanPoint& p : f0.sharp) EXPECT_LT(stepsFromGap(p), 5.5f);

	o.max_azimuth_gap = 3;
	FeatureExtractor fx(o);
	const FeatureSet f = fx.extract(rs);
	EXPECT_TRUE(f.sharp.empty());
	EXPECT_TRUE(f.less_sharp.empty());
	EXPECT_GE(f.flat.size(), 6u * 4u - 2u);
	// The window of a point W = 5 steps from the border no longer reaches across it.
	for (const ScanPoint& p : f.flat) EXPECT_GT(stepsFromGap(p), 4.5f);
	for (const ScanPoint& p : f.less_flat) EXPECT_GT(stepsFromGap(p), 4.5f);
	for (const ScanPoint& p : f.less_flat) EXPECT_NEAR(p.p.head<2>().norm(), 10.0f, 0.01f);
}

TEST(Features, Hdl64UrbanScanCounts)
{
	Path path;
	path.add(60, 0.0);
	const World w = urbanWorld(path, 2);
	const LoamOptions o = hdl64Options();
	ScanPreprocessor pre(o.scan);
	FeatureExtractor fx(o.features);
	const FeatureSet f = fx.extract(pre.process(scan(w, hdl64(), lidarPoseAt(path, 20))));
	EXPECT_GT(f.sharp.size(), 200u);
	EXPECT_LE(f.sharp.size(), 64u * 6u * 2u);
	EXPECT_EQ(f.flat.size(), 64u * 6u * 4u);
	EXPECT_GT(f.less_flat.size(), 10000u);
	for (const auto* set : {&f.sharp, &f.less_sharp, &f.flat, &f.less_flat})
		for (std::size_t i = 1; i < set->size(); ++i) ASSERT_LE((*set)[i - 1].ring, (*set)[i].ring);  // ring order
}
}  // namespace vlo::loam::test
