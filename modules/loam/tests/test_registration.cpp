// Known rigid motions between two synthetic scans of a structured world are recovered.
#include <gtest/gtest.h>
#include <vlo/loam/lidar_odometry.h>

#include <cstdio>
#include <random>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
Eigen::Isometry3d motion(double x, double y, double z, double yaw_deg, double pitch_deg, double roll_deg)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	const double k = M_PI / 180;
	T.linear() = (Eigen::AngleAxisd(yaw_deg * k, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch_deg * k, Eigen::Vector3d::UnitY()) *
		Eigen::AngleAxisd(roll_deg * k, Eigen::Vector3d::UnitX()))
					 .toRotationMatrix();
	T.translation() = Eigen::Vector3d(x, y, z);
	return T;
}

struct Pair
{
	PointCloud a, b;
	Eigen::Isometry3d truth;  ///< pose of scan b in scan a's frame
};

Pair scanPair(bool hdl, const Eigen::Isometry3d& delta, unsigned seed)
{
	Path path;
	path.add(80, 0.0);
	const World w = urbanWorld(path, seed);
	LidarModel m = hdl ? hdl64() : vlp16();
	m.noise_sigma = 0.01;
	std::mt19937 rng(seed);
	const Eigen::Isometry3d A = lidarPoseAt(path, 25);
	return Pair{scan(w, m, A, &rng), scan(w, m, A * delta, &rng), delta};
}

const std::vector<Eigen::Isometry3d>& motions()
{
	static const std::vector<Eigen::Isometry3d> m = {
		motion(0.9, 0.05, 0.02, 1.5, 0.3, -0.2), motion(1.4, -0.1, 0.0, -3.0, 0.0, 0.0), motion(0.3, 0.3, 0.05, 0.5, -0.4, 0.4)};
	return m;
}

void expectRecovered(bool hdl, const LoamOptions& o)
{
	int k = 0;
	for (const Eigen::Isometry3d& delta : motions())
	{
		const Pair p = scanPair(hdl, delta, 40 + k++);
		LidarOdometry lo(o);
		lo.process(0.0, p.a, std::nullopt);
		const LidarOdometryResult r = lo.process(0.1, p.b, std::nullopt);
		std::printf("%s motion %d: %.4f m, %.4f deg (scan-to-scan %.4f m, %.4f deg), min eigenvalue %.0f\n", hdl ? "HDL-64" : "VLP-16", k,
			translationError(r.pose, p.truth), rotationErrorDeg(r.pose, p.truth),
			translationError(r.odometry.T_prev_curr, p.truth), rotationErrorDeg(r.odometry.T_prev_curr, p.truth),
			r.mapping.degeneracy.min_eigenvalue);
		EXPECT_EQ(r.status, LidarFrameStatus::Ok) << r.reason;
		EXPECT_LT(translationError(r.pose, p.truth), 0.01);
		EXPECT_LT(rotationErrorDeg(r.pose, p.truth), 0.05);
		EXPECT_TRUE(r.odometry.ok) << r.odometry.reason;
		EXPECT_LT(translationError(r.odometry.T_prev_curr, p.truth), 0.05);  // scan-to-scan alone is coarser
		EXPECT_LT(rotationErrorDeg(r.odometry.T_prev_curr, p.truth), 0.2);
		EXPECT_FALSE(r.mapping.degeneracy.degenerate);
	}
}
}  // namespace

TEST(Registration, Hdl64KnownMotions) { expectRecovered(true, hdl64Options()); }

TEST(Registration, Vlp16KnownMotions) { expectRecovered(false, vlp16Options()); }

TEST(Registration, KdTreeNeighboursAgreeWithRingSearch)
{
	LoamOptions o = hdl64Options();
	o.odometry.use_kdtree = true;
	o.mapping.enabled = false;
	const Pair p = scanPair(true, motions()[0], 7);
	LidarOdometry lo(o);
	lo.process(0.0, p.a, std::nullopt);
	const LidarOdometryResult r = lo.process(0.1, p.b, std::nullopt);
	EXPECT_LT(translationError(r.pose, p.truth), 0.05);
	EXPECT_LT(rotationErrorDeg(r.pose, p.truth), 0.2);
}

TEST(Registration, ExternalPriorRescuesALargeMotion)
{
	// 4.5 m and 12 deg in one frame: from a standing start the constant-velocity guess (identity)
	// is too far off, a visual-odometry-like guess (10 cm, 0.5 deg off) is not.
	const Eigen::Isometry3d delta = motion(4.5, 0.4, 0.0, 12.0, 0.0, 0.0);
	const Pair p = scanPair(true, delta, 9);
	LoamOptions o = hdl64Options();
	o.prior.source = "external";
	LidarOdometry lo(o);
	lo.process(0.0, p.a, std::nullopt);
	const Eigen::Isometry3d vo = delta * motion(0.1, -0.05, 0.0, 0.5, 0.0, 0.0);
	const LidarOdometryResult r = lo.process(0.1, p.b, vo);
	EXPECT_EQ(r.prior_source, "external");
	EXPECT_LT(translationError(r.pose, p.truth), 0.01);
	EXPECT_LT(rotationErrorDeg(r.pose, p.truth), 0.05);

	// From the identity, A-LOAM's two rounds of scan-to-scan miss it; rounds that go on while the
	// pose still moves (the default max_rounds) reach it too, and so does the first motion's search
	// from several translations (the default cold start).
	LoamOptions two = hdl64Options();
	two.odometry.max_rounds = two.odometry.solver.outer_iterations;
	two.odometry.cold_start_range = 0;
	LoamOptions rounds = hdl64Options();
	rounds.odometry.cold_start_range = 0;
	for (const LoamOptions& oc : {two, rounds, hdl64Options()})
	{
		LidarOdometry cv(oc);
		cv.process(0.0, p.a, std::nullopt);
		const LidarOdometryResult rc = cv.process(0.1, p.b, vo);  // the constant-velocity prior ignores vo
		EXPECT_EQ(rc.prior_source, oc.odometry.cold_start_range > 0 ? "cold_start" : "constant_velocity");
		if (oc.odometry.max_rounds == 2) EXPECT_GT(translationError(rc.pose, p.truth), 0.05);
		else EXPECT_LT(translationError(rc.pose, p.truth), 0.01);
	}
}
}  // namespace vlo::loam::test

namespace vlo::loam::test
{
TEST(Registration, CorridorIsFlaggedDegenerate)
{
	// Two long smooth walls and the ground: nothing fixes the position along the corridor.
	const World corridor = corridorWorld(400, 4.0, 5.0);
	const World street = [] {
		Path p;
		p.add(80, 0.0);
		return urbanWorld(p, 3);
	}();
	const auto run = [](const World& w) {
		LoamOptions o = hdl64Options();
		o.mapping.edges = "auto";
		LidarOdometry lo(o);
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.translation() = Eigen::Vector3d(20, 0.3, 1.73);
		lo.process(0.0, scan(w, hdl64(), T), std::nullopt);
		T.translation().x() += 1.0;
		return lo.process(0.1, scan(w, hdl64(), T), std::nullopt);
	};
	const LidarOdometryResult c = run(corridor), s = run(street);
	std::printf("min eigenvalue of J^T J: corridor %.3g, street %.3g\n", c.mapping.degeneracy.min_eigenvalue,
		s.mapping.degeneracy.min_eigenvalue);
	EXPECT_TRUE(c.mapping.degeneracy.degenerate);
	EXPECT_GT(std::abs(c.mapping.degeneracy.weakest(3)), 0.9);  // along the corridor (x)
	EXPECT_FALSE(s.mapping.degeneracy.degenerate);
	EXPECT_GT(s.mapping.degeneracy.min_eigenvalue, 10 * c.mapping.degeneracy.min_eigenvalue);
	// edges = auto: lines are sought where the planes leave the translation weak, and only there.
	EXPECT_TRUE(c.mapping.used_edges);
	EXPECT_FALSE(s.mapping.used_edges);
}
TEST(Registration, ScanToMapRoundsGoOnOnlyWhereThePlanesFixTheTranslation)
{
	// A scan aligned to a map of three noisy scans from a guess 12 cm and 0.5 deg off (a VO step
	// that went straight to scan-to-map): in a street the rounds go on while the pose moves and
	// reach the truth, where A-LOAM's two stop short; between a corridor's walls they stop at two,
	// which they would not if the planes' information did not stop them.
	struct Out
	{
		double error;
		int rounds;
	};
	const auto align = [](const World& w, int max_rounds, double weak_plane_information) {
		LoamOptions o = hdl64Options();
		o.mapping.max_rounds = max_rounds;
		o.mapping.weak_plane_information = weak_plane_information;
		// The rounds alone: every line matched whatever it was seen from and however it lies (with
		// flat lines from nearby only, or without lines strewn over a surface, the street's two rounds
		// already reach 0.7 / 0.5 mm from this guess).
		o.mapping.view_dependent_reach = 0;
		o.mapping.edge_flatness_ratio = 0;
		ScanPreprocessor pre(o.scan);
		FeatureExtractor fx(o.features);
		ScanToMap mapper(o.mapping);
		LidarModel lidar = hdl64();
		lidar.noise_sigma = 0.02;
		std::mt19937 rng(5);
		Eigen::Isometry3d A = Eigen::Isometry3d::Identity();
		A.translation() = Eigen::Vector3d(20, 0.3, 1.73);
		for (int k = -2; k <= 0; ++k)
		{
			const Eigen::Isometry3d Ak = A * motion(k, 0, 0, 0, 0, 0);
			mapper.insert(fx.extract(pre.process(scan(w, lidar, Ak, &rng))), Ak);
		}
		const Eigen::Isometry3d B = A * motion(1.0, 0, 0, 0, 0, 0);
		const ScanToMap::Result r = mapper.align(
			mapper.prepare(fx.extract(pre.process(scan(w, lidar, B, &rng)))), B * motion(0.1, -0.06, 0.02, 0.5, 0, 0));
		EXPECT_TRUE(r.ok);
		return Out{translationError(r.T_map_curr, B), r.rounds};
	};
	const World street = [] {
		Path p;
		p.add(80, 0.0);
		return urbanWorld(p, 3);
	}();
	const World corridor = corridorWorld(400, 4.0, 5.0);
	const MappingOptions d;
	const int two = d.solver.outer_iterations;
	const Out s2 = align(street, two, d.weak_plane_information), s = align(street, d.max_rounds, d.weak_plane_information);
	const Out c = align(corridor, d.max_rounds, d.weak_plane_information), c_on = align(corridor, d.max_rounds, 0);
	const Out c2 = align(corridor, two, d.weak_plane_information);
	std::printf("scan-to-map from 12 cm off: street %.4f m in %d rounds (two rounds: %.4f m); corridor %.4f m in %d rounds "
				"(two rounds: %.4f m), %d without the planes' check (%.4f m)\n",
		s.error, s.rounds, s2.error, c.error, c.rounds, c2.error, c_on.rounds, c_on.error);
	EXPECT_GT(s.rounds, two);
	EXPECT_LT(s.error, 0.003);
	EXPECT_GT(s2.error, 3 * s.error);
	// The corridor's rounds stop once they no longer settle: nearer than A-LOAM's two, far from sliding.
	EXPECT_LT(c.rounds, d.max_rounds);
	EXPECT_LE(c.error, c2.error);
	EXPECT_LT(c.error, 0.5 * c_on.error);
}

TEST(Registration, PlaneMatchesNeedAFourthPointOnThePlane)
{
	// Scan-to-scan plane matches at the true motion, against the reference scan as measured and
	// against the same scan with its plane points scattered +-0.15 m along their beams (leaves in a
	// crown): three scattered points still span a "plane", a fourth one seldom lies on it.
	const Pair p = scanPair(false, motion(0.8, 0.05, 0, 1.0, 0, 0), 5);
	const LoamOptions o = vlp16Options();
	ScanPreprocessor pre(o.scan);
	FeatureExtractor fx(o.features);
	const FeatureSet ref = fx.extract(pre.process(p.a)), curr = fx.extract(pre.process(p.b));
	FeatureSet leaves = ref;
	std::mt19937 rng(7);
	std::uniform_real_distribution<float> depth(-0.15f, 0.15f);
	for (ScanPoint& q : leaves.less_flat) q.p *= 1.0f + depth(rng) / q.p.norm();

	const auto planes = [&](const FeatureSet& reference, double check) {
		OdometryOptions oo = o.odometry;
		oo.plane_max_distance = check;
		ScanToScanOdometry odo(oo, RingModel(o.scan));
		odo.setReference(reference);
		Matches m;
		odo.findMatches(curr, p.truth, m);
		return static_cast<double>(m.planes.size());
	};
	const double check = o.odometry.plane_max_distance;  // the default
	const double solid = planes(ref, 0), solid_checked = planes(ref, check);
	const double crown = planes(leaves, 0), crown_checked = planes(leaves, check);
	std::printf("plane matches: solid %.0f, checked %.0f; scattered %.0f, checked %.0f\n", solid, solid_checked, crown, crown_checked);
	ASSERT_GT(solid, 100);
	EXPECT_GT(crown, 0.9 * solid);  // without the check the leaves match as well as solid surfaces
	EXPECT_GT(solid_checked, 0.8 * solid);
	EXPECT_LT(crown_checked, 0.5 * crown);
}

TEST(Registration, RoughPlanesHoldWhatSmoothOnesLeaveFree)
{
	// A corridor walled by heaps of 0.3 m blocks, each set off up to 0.15 m and turned up to 45 deg
	// (a hedge, a row of canopies): hardly any 8 wall points lie within 5 cm of a plane. Scan-to-map
	// of a VLP-16 scan, planes only, from a guess 0.3 m off along the corridor: with planes up to
	// 0.25 m (the default) it comes back; with smooth planes only too few match and the guess stands.
	World w;
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> turn(-45, 45), off(-0.15, 0.15);
	for (double x = -40; x < 40; x += 0.3)
		for (double z = 0.15; z < 3; z += 0.3)
			for (int side : {-1, 1})
				w.boxes.push_back(Box{Eigen::Vector3d(x + off(rng), side * 4.5 + off(rng), z + off(rng)), Eigen::Vector3d(0.15, 0.15, 0.15),
					turn(rng) * M_PI / 180});
	LidarModel m = vlp16();
	m.noise_sigma = 0.01;
	const Eigen::Isometry3d A = planarPose(0, 0, 0) * Eigen::Translation3d(0, 0, 1.73), B = A * planarPose(1.2, 0, 0);
	const auto align = [&](double rough_plane_max_distance) {
		LoamOptions o = vlp16Options();
		o.mapping.rough_plane_max_distance = rough_plane_max_distance;
		o.mapping.free_space_radius = 0;  // the guess is far off: nothing has moved
		o.mapping.edges = "off";  // the planes alone
		ScanFeatureExtractor fx(o);
		ScanToMap mapper(o.mapping);
		mapper.insert(fx.extract(scan(w, m, A, &rng)).features, A);
		const ScanToMap::Result r = mapper.align(mapper.prepare(fx.extract(scan(w, m, B, &rng)).features), B * planarPose(-0.3, 0, 0));
		const Eigen::Vector3d e = (B.inverse() * r.T_map_curr).translation();
		std::printf("rough planes up to %.2f m: used %d, %d matches, %d rounds, off by %.3f %.3f %.3f m\n", rough_plane_max_distance,
			r.used_rough_planes, r.n_planes + r.n_edges, r.rounds, e.x(), e.y(), e.z());
		return r;
	};
	const ScanToMap::Result smooth = align(0.0), rough = align(MappingOptions().rough_plane_max_distance);
	EXPECT_FALSE(smooth.used_rough_planes);
	EXPECT_FALSE(smooth.ok);
	EXPECT_GT(translationError(smooth.T_map_curr, B), 0.29);
	EXPECT_TRUE(rough.used_rough_planes);
	EXPECT_GT(rough.n_planes, 2 * smooth.n_planes);
	EXPECT_LT(translationError(rough.T_map_curr, B), 0.05);
}
}  // namespace vlo::loam::test
