// The voxel map (exact neighbours, downsampling, bounds) and a bounded map over a
// long drive.
#include <gtest/gtest.h>
#include <vlo/loam/lidar_odometry.h>
#include <vlo/loam/voxel_map.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
TEST(Map, KnnIsExactWithinHalfAVoxel)
{
	std::mt19937 rng(2);
	std::uniform_real_distribution<float> U(-10, 10);
	std::vector<Eigen::Vector3f> pts;
	for (int i = 0; i < 5000; ++i) pts.emplace_back(U(rng), U(rng), 0.2f * U(rng));
	VoxelMap map(2.0, 0.01, 1000);
	ASSERT_EQ(map.insert(pts), pts.size());
	for (int t = 0; t < 500; ++t)
	{
		const Eigen::Vector3f q(U(rng), U(rng), 0.2f * U(rng));
		std::vector<float> d;
		for (const auto& p : pts)
			if ((p - q).norm() < 1.0f) d.push_back((p - q).norm());
		std::sort(d.begin(), d.end());
		Eigen::Vector3f nn[8];
		const int n = map.knn(q, 8, 1.0f, nn);
		ASSERT_EQ(n, static_cast<int>(std::min<std::size_t>(8, d.size())));
		for (int i = 0; i < n; ++i) ASSERT_NEAR((nn[i] - q).norm(), d[i], 1e-5);
	}
}

TEST(Map, OnePointPerCellAndFarVoxelsDropped)
{
	VoxelMap map(2.0, 0.5, 100);
	std::vector<Eigen::Vector3f> pts;
	for (int i = 0; i < 40; ++i)
		for (int j = 0; j < 40; ++j) pts.emplace_back(0.1f * i + 0.01f, 0.1f * j + 0.01f, 0.05f);  // 4 m x 4 m
	EXPECT_EQ(map.insert(pts), 64u);  // (4 / 0.5)^2 cells
	EXPECT_EQ(map.insert(pts), 0u);  // revisiting adds nothing
	EXPECT_EQ(map.numVoxels(), 4u);
	std::vector<Eigen::Vector3f> far = {Eigen::Vector3f(100, 0, 0), Eigen::Vector3f(-100, 5, 0)};
	map.insert(far);
	EXPECT_EQ(map.numPoints(), 66u);
	EXPECT_EQ(map.removeFar(Eigen::Vector3f::Zero(), 50.0f), 2u);
	EXPECT_EQ(map.numPoints(), 64u);
	EXPECT_EQ(map.numVoxels(), 4u);
	std::vector<Eigen::Vector3f> all;
	map.appendPoints(all);
	EXPECT_EQ(all.size(), 64u);
}

TEST(Map, LinesThatDependOnTheViewAreMatchedOnlyFromNearby)
{
	// Edge points (map frame) of a vertical crease line 5 m ahead, of a flat line along the road 3 m
	// to the left and 1.5 m down (a curb), and of a second vertical line on a silhouette, 0.21 m
	// apart, seen from 4 m behind the pose the probes are matched at: the silhouette's bearing was
	// -18.8 deg then, -31.0 deg now.
	FeatureSet f;
	const auto add = [&](const Eigen::Vector3f& p, bool silhouette) {
		ScanPoint q;
		q.p = p + Eigen::Vector3f(4, 0, 0);
		f.less_sharp.push_back(q);
		f.less_sharp_silhouette.push_back(silhouette ? 1 : 0);
	};
	for (int i = 0; i < 12; ++i) add(Eigen::Vector3f(5.1f, 0.1f, -1.4f + 0.21f * i), false);
	for (int i = 0; i < 16; ++i) add(Eigen::Vector3f(3.1f + 0.21f * i, 3.1f, -1.5f), false);
	for (int i = 0; i < 12; ++i) add(Eigen::Vector3f(5.1f, -3.1f, -1.4f + 0.21f * i), true);
	Eigen::Isometry3d seen_from = Eigen::Isometry3d::Identity();
	seen_from.translation().x() = -4;
	ScanToMap::Input probes;
	probes.edges = {Eigen::Vector3f(5.15f, 0.1f, 0.1f), Eigen::Vector3f(5.0f, 3.15f, -1.5f), Eigen::Vector3f(5.15f, -3.1f, 0.1f)};
	probes.edge_silhouette = {0, 0, 0};
	const auto matches = [&](double reach, double min_elevation_deg, double outline_view_change_deg) {
		MappingOptions o;
		o.view_dependent_reach = reach;
		o.min_line_elevation_deg = min_elevation_deg;
		o.outline_view_change_deg = outline_view_change_deg;
		ScanToMap mapper(o);
		mapper.insert(f, seen_from);
		Matches m;
		mapper.findMatches(probes, Eigen::Isometry3d::Identity(), {true, false}, m);
		return m.edges.size();
	};
	EXPECT_EQ(matches(0, 53, 0), 3u);  // any reach, any view (A-LOAM)
	EXPECT_EQ(matches(5, 53, 20), 3u);  // seen from 4 m, 12 deg away: near enough
	EXPECT_EQ(matches(3, 53, 20), 2u);  // too far for the curb's flat line
	EXPECT_EQ(matches(3, 53, 10), 1u);  // ... and the silhouette seen from 12 deg away
	EXPECT_EQ(matches(3, 0, 10), 2u);  // no line counts as flat: only the silhouette goes
}

TEST(Map, OutlinesAreFitFromViewsLikeTheCurrentOne)
{
	// A pole's outline 10 m to the right went into the map twice: seen from 6 m behind (bearing
	// -59 deg, now -90: the outline of another side of the body, 5 cm ahead of the probe) and from
	// 1 m behind (-87 deg, 0.4 m behind the probe). The line is fit from the similar view.
	FeatureSet near_view, other_view;
	for (int i = 0; i < 40; ++i)
	{
		ScanPoint q;
		q.p = Eigen::Vector3f(0.05f, -10.0f, -1.1f + 0.06f * i);
		other_view.less_sharp.push_back(q);
		other_view.less_sharp_silhouette.push_back(1);
		q.p.x() = -0.4f;
		near_view.less_sharp.push_back(q);
		near_view.less_sharp_silhouette.push_back(1);
	}
	const auto lineThrough = [&](double outline_view_change_deg) {
		MappingOptions o;
		o.map_edge_resolution = 0.05;
		o.outline_view_change_deg = outline_view_change_deg;
		ScanToMap mapper(o);
		for (const auto& [f, x] : {std::pair{other_view, -6.0f}, std::pair{near_view, -1.0f}})
		{
			Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
			T.translation().x() = x;
			FeatureSet in_sensor = f;
			for (ScanPoint& q : in_sensor.less_sharp) q.p.x() -= x;
			mapper.insert(in_sensor, T);
		}
		ScanToMap::Input probe;
		probe.edges = {Eigen::Vector3f(0.0f, -10.0f, 0.1f)};
		probe.edge_silhouette = {1};
		Matches m;
		mapper.findMatches(probe, Eigen::Isometry3d::Identity(), {true, false}, m);
		return m.edges.empty() ? std::nan("") : m.edges[0].a.x();
	};
	EXPECT_NEAR(lineThrough(0), 0.05, 0.01);  // A-LOAM: the nearest points, another side of the body
	EXPECT_NEAR(lineThrough(20), -0.4, 0.01);  // within 20 deg: the view from 1 m behind
	EXPECT_TRUE(std::isnan(lineThrough(3)));  // no view within 3 deg
}

TEST(Map, LinesAreMatchedOnlyToPointsSeenFromASimilarRange)
{
	// Where a real beam finds an outline or a corner depends on the range it is seen from. A pole
	// 10 m ahead goes into the map from 10, 12 or 8 m away; the probe on it is seen from 10.05 m.
	const auto matches = [](float seen_from_x, double ratio) {
		FeatureSet f;
		for (int i = 0; i < 12; ++i)
		{
			ScanPoint q;
			q.p = Eigen::Vector3f(10.0f - seen_from_x, 0.1f, -1.4f + 0.21f * i);
			f.less_sharp.push_back(q);
			f.less_sharp_silhouette.push_back(0);
		}
		MappingOptions o;
		o.edge_range_ratio = ratio;
		ScanToMap mapper(o);
		Eigen::Isometry3d seen_from = Eigen::Isometry3d::Identity();
		seen_from.translation().x() = seen_from_x;
		mapper.insert(f, seen_from);
		ScanToMap::Input probe;
		probe.edges = {Eigen::Vector3f(10.05f, 0.1f, 0.1f)};
		probe.edge_silhouette = {0};
		Matches m;
		mapper.findMatches(probe, Eigen::Isometry3d::Identity(), {true, false}, m);
		return m.edges.size();
	};
	EXPECT_EQ(matches(0, 1.1), 1u);  // seen from 10.0-10.1 m
	EXPECT_EQ(matches(-2, 1.1), 0u);  // from 12.0-12.1 m: beyond 1.1 x 10.05 m
	EXPECT_EQ(matches(-2, 1.25), 1u);  // ... within 1.25 x
	EXPECT_EQ(matches(2, 1.1), 0u);  // from 8.0-8.1 m: 10.05 m is beyond 1.1 x that
	EXPECT_EQ(matches(-2, 0), 1u);  // off: any range (A-LOAM)
}

TEST(Map, PointsStrewnOverASurfaceAreNoLine)
{
	// Edge map points of a pole 5 m ahead on the right (1 cm of noise across it) and of a band on a
	// wall 3 m to the left: along the band 2.5 m, across it within the wall +-8 cm, out of the wall
	// +-5 mm. Both pass A-LOAM's test (largest spread > 3x the middle); the wall's points spread across
	// their "line" within a surface.
	FeatureSet f;
	const auto add = [&](float x, float y, float z) {
		ScanPoint q;
		q.p = Eigen::Vector3f(x, y, z);
		f.less_sharp.push_back(q);
		f.less_sharp_silhouette.push_back(0);
	};
	for (int i = 0; i < 12; ++i)
	{
		const float s = i % 2 == 0 ? 1.0f : -1.0f, s3 = i % 3 == 0 ? 1.0f : -1.0f;
		add(5.0f + 0.01f * s, -3.0f + 0.01f * s3, -1.2f + 0.21f * i);
		add(4.0f + 0.21f * i, 3.0f + 0.005f * s, -0.5f + 0.08f * i + 0.08f * s);
	}
	ScanToMap::Input probes;
	probes.edges = {Eigen::Vector3f(5.0f, -3.0f, 0.1f), Eigen::Vector3f(5.05f, 3.0f, -0.1f)};
	probes.edge_silhouette = {0, 0};
	const auto matches = [&](double flatness) {
		MappingOptions o;
		o.edge_flatness_ratio = flatness;
		o.view_dependent_reach = 0;
		ScanToMap mapper(o);
		mapper.insert(f, Eigen::Isometry3d::Identity());
		Matches m;
		mapper.findMatches(probes, Eigen::Isometry3d::Identity(), {true, false}, m);
		return m.edges.size();
	};
	EXPECT_EQ(matches(0), 2u);  // A-LOAM: the wall's band is a line too
	EXPECT_EQ(matches(5), 1u);  // only the pole
	EXPECT_EQ(matches(MappingOptions().edge_flatness_ratio), 1u);  // the default
}

TEST(Map, ScanToMapStaysBoundedOverFiveKilometres)
{
	// A scan-like point set (ground and two walls within 60 m) inserted every 5 m along a 5 km
	// road: the map must stop growing once the vehicle is a map radius away from the start.
	MappingOptions o;
	o.map_radius = 80;
	ScanToMap mapper(o);
	std::mt19937 rng(3);
	std::uniform_real_distribution<float> U(-60, 60), H(0, 8);
	std::size_t at_start_plateau = 0, peak = 0;
	for (int i = 0; i < 1000; ++i)
	{
		FeatureSet f;
		for (int k = 0; k < 2000; ++k)
		{
			ScanPoint p;
			const int kind = k % 3;
			p.p = kind == 0 ? Eigen::Vector3f(U(rng), 0.25f * U(rng), -1.7f) : Eigen::Vector3f(U(rng), kind == 1 ? 12.f : -12.f, H(rng));
			p.ring = k % 16;
			f.less_flat.push_back(p);
			if (k % 10 == 0) f.less_sharp.push_back(p);
		}
		std::sort(f.less_flat.begin(), f.less_flat.end(), [](const ScanPoint& a, const ScanPoint& b) { return a.ring < b.ring; });
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.translation().x() = 5.0 * i;
		mapper.insert(f, T);
		const std::size_t n = mapper.edgeMap().numPoints() + mapper.planeMap().numPoints();
		if (i == 40) at_start_plateau = n;  // 200 m: more than a map diameter driven
		peak = std::max(peak, n);
	}
	EXPECT_GT(at_start_plateau, 0u);
	EXPECT_LT(peak, at_start_plateau * 11 / 10);
}

TEST(Map, LongDriveMapIsBounded)
{
	Path path;
	path.add(100, 0.0);
	path.add(50, 1.0 / 40);
	path.add(100, 0.0);
	const World w = urbanWorld(path, 5);
	LoamOptions o = vlp16Options();
	o.mapping.map_radius = 40;
	LidarOdometry lo(o);
	std::size_t at_80m = 0, peak = 0;
	double max_err = 0;
	const Eigen::Isometry3d T0 = lidarPoseAt(path, 0);
	for (int i = 0; i * 2.5 < path.length(); ++i)
	{
		const Eigen::Isometry3d truth = lidarPoseAt(path, 2.5 * i);
		const LidarOdometryResult r = lo.process(0.1 * i, scan(w, vlp16(), truth), std::nullopt);
		const std::size_t n = r.map_edge_points + r.map_plane_points;
		EXPECT_EQ(n, lo.mapPoints().size());
		if (i == 32) at_80m = n;
		peak = std::max(peak, n);
		max_err = std::max(max_err, translationError(r.pose, T0.inverse() * truth));
	}
	std::printf("map points after 80 m: %zu, peak over 250 m: %zu, max position error %.3f m\n", at_80m, peak, max_err);
	EXPECT_LT(peak, at_80m * 3 / 2);  // buildings vary along the street; no steady growth
	EXPECT_LT(max_err, 0.5);
}
}  // namespace vlo::loam::test
