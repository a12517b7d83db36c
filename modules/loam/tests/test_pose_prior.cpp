// [loam.prior] motion_sigma: the external motion as a residual of scan-to-map's solve, weighed by its
// information against the map's lines and planes.
#include <gtest/gtest.h>
#include <vlo/loam/lidar_odometry.h>
#include <vlo/loam/pose_prior.h>
#include <vlo/loam/pose_solver.h>

#include <cstdio>
#include <cstdlib>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
/// Plane matches of points at the identity pose: `n_walls` on each of two walls y = +-4 and
/// `n_floor` on the floor z = 0, spread along x; with `n_end` on a wall x = 30 ahead as well. The
/// walls' points are centred on the origin in x and z, so that no rotation imitates a translation.
Matches corridorMatches(int n_walls, int n_floor, int n_end)
{
	Matches m;
	for (int i = 0; i < n_walls; ++i)
	{
		const double x = -20 + 40.0 * (i + 0.5) / n_walls, z = -0.995 + 0.01 * (i % 200);
		m.planes.push_back({Eigen::Vector3d(x, 4, z), Eigen::Vector3d(0, 1, 0), -4});
		m.planes.push_back({Eigen::Vector3d(x, -4, z), Eigen::Vector3d(0, -1, 0), -4});
	}
	for (int i = 0; i < n_floor; ++i)
		m.planes.push_back({Eigen::Vector3d(-20 + 40.0 * (i + 0.5) / n_floor, -3 + 6.0 * (i % 7) / 6, 0), Eigen::Vector3d(0, 0, 1), 0});
	for (int i = 0; i < n_end; ++i)
		m.planes.push_back({Eigen::Vector3d(30, -3 + 6.0 * (i % 9) / 8, 0.5 + 0.1 * (i % 13)), Eigen::Vector3d(1, 0, 0), -30});
	return m;
}

SolverOptions exactSolver()
{
	SolverOptions o;
	o.loss = "none";  // least squares: closed-form answers
	o.max_solver_iterations = 20;
	return o;
}

/// A prior at `at` with translation information `info` along each axis and a rotation one of `rot_info`.
PosePrior priorAt(const Eigen::Isometry3d& at, double info, double rot_info)
{
	return posePriorInScanAxes(at, rot_info * Eigen::Matrix3d::Identity(), info * Eigen::Matrix3d::Identity());
}
}  // namespace

TEST(PosePrior, DecidesTheDirectionTheGeometryLeavesFree)
{
	// Two walls and a floor fix y, z and the rotation, nothing fixes x. The prior says x = 0.30 and
	// y = 0.10 with the information of one plane match per axis: x is the prior's, y the walls'
	// (400 wall matches against 1: 0.10 / 401 = 0.25 mm).
	const Matches m = corridorMatches(200, 200, 0);
	const PosePrior prior = priorAt(planarPose(0.30, 0.10, 0), 1.0, 1.0);
	Eigen::Isometry3d T = planarPose(0.8, -0.05, 0.5);  // the guess
	const SolveReport rep = solvePose(m, exactSolver(), T, &prior);
	std::printf("corridor with a prior (%d iterations): x %.6f y %.6f z %.6f yaw %.5f deg\n", rep.iterations, T.translation().x(), T.translation().y(),
		T.translation().z(), rotationErrorDeg(T, Eigen::Isometry3d::Identity()));
	EXPECT_NEAR(T.translation().x(), 0.30, 1e-6);
	EXPECT_NEAR(T.translation().y(), 0.10 / 401, 1e-6);
	EXPECT_NEAR(T.translation().z(), 0.0, 1e-6);
	EXPECT_LT(rotationErrorDeg(T, Eigen::Isometry3d::Identity()), 1e-4);
	// The report's J^T J is the matches' alone: nothing along x.
	EXPECT_NEAR(rep.JtJ(3, 3), 0.0, 1e-9);
	// Free along x, the prior costs the walls nothing there; its 0.10 m along y costs them
	// (1 x 0.10 x 400/401)^2 / 400 = 2.5e-5 m^2.
	EXPECT_NEAR(geometryCostOfPrior(prior, rep.JtJ, T), 0.01 * 400 / (401.0 * 401.0), 1e-7);
	// Without the prior x stays wherever the guess put it.
	Eigen::Isometry3d alone = planarPose(0.8, -0.05, 0.5);
	solvePose(m, exactSolver(), alone);
	EXPECT_NEAR(alone.translation().x(), 0.8, 0.05);
}

TEST(PosePrior, AWeakWrongPriorIsOverriddenByTheGeometry)
{
	// Walls, floor and an end wall fix every direction. A prior 0.5 m and 2 deg off with the weight of
	// one match: the geometry decides, the prior moves x by 0.5 / (1 + 100 end-wall matches).
	const Matches m = corridorMatches(200, 200, 100);
	const PosePrior weak = priorAt(planarPose(0.5, 0.0, 0.0), 1.0, 1.0);
	Eigen::Isometry3d T = planarPose(0.2, 0.1, 1.0);
	const SolveReport rep = solvePose(m, exactSolver(), T, &weak);
	std::printf("wrong weak prior: x %.6f (0.5 / 101 = %.6f)\n", T.translation().x(), 0.5 / 101);
	EXPECT_NEAR(T.translation().x(), 0.5 / 101, 2e-4);  // the end wall's rotation coupling: 1e-4
	EXPECT_LT(std::abs(T.translation().y()), 1e-4);
	// The prior hardly raised the matches' cost: it is kept ...
	const double weak_cost = geometryCostOfPrior(weak, rep.JtJ, T);
	// ... where the same prior with the information of 10000 matches would drag the end wall along:
	const PosePrior strong = priorAt(planarPose(0.5, 0.0, 0.0), 1e4, 1e4);
	Eigen::Isometry3d Ts = planarPose(0.2, 0.1, 1.0);
	const SolveReport rep_s = solvePose(m, exactSolver(), Ts, &strong);
	const double strong_cost = geometryCostOfPrior(strong, rep_s.JtJ, Ts);
	std::printf("matches' cost raised by the prior: weak %.3g m^2, strong %.3g m^2 (x %.4f)\n", weak_cost, strong_cost,
		Ts.translation().x());
	EXPECT_NEAR(weak_cost, 100 * std::pow(0.5 / 101, 2), 1e-4);  // 100 matches each 4.9 mm off
	EXPECT_GT(Ts.translation().x(), 0.49);
	EXPECT_GT(strong_cost, 1000 * weak_cost);
}

TEST(PosePrior, InformationFollowsTheSourcesQuality)
{
	PriorOptions o;
	o.motion_sigma = 0.01;  // with matches of 0.02 m: 4 matches' worth per axis
	const Eigen::Isometry3d motion = planarPose(1.0, 0.0, 0.0);
	const auto info = [&](ExternalMotionQuality q) {
		return externalMotionPrior(Eigen::Isometry3d::Identity(), motion, q, o, 0.02).information;
	};
	EXPECT_NEAR(info({})(3, 3), 4.0, 1e-9);
	EXPECT_NEAR(info({100, std::nan("")})(4, 4), 4.0, 1e-9);
	EXPECT_NEAR(info({25, std::nan("")})(4, 4), 1.0, 1e-9);  // a quarter of the features: a quarter of the information
	// A 1 % length error on 1 m adds (0.01 m)^2 along the motion: half the information along x only.
	const Matrix6d l = info({100, 0.01});
	EXPECT_NEAR(l(3, 3), 2.0, 1e-9);
	EXPECT_NEAR(l(4, 4), 4.0, 1e-9);
	// Turned into the map's axes: the previous pose turned by 90 deg swaps x and y.
	const Matrix6d turned = externalMotionPrior(planarPose(0, 0, 90), motion, {100, 0.01}, o, 0.02).information;
	// Roll and pitch: 0.005 deg against matches of 0.02 m, 5.25e6 matches' worth per radian^2; yaw 0.05 deg,
	// a hundredth of that, about the scan's z axis (the map's z after any turn about it).
	EXPECT_NEAR(l(0, 0), std::pow(0.02 / (0.005 * M_PI / 180), 2), 1.0);
	EXPECT_NEAR(l(1, 1), l(0, 0), 1e-6);
	EXPECT_NEAR(l(2, 2), std::pow(0.02 / (0.05 * M_PI / 180), 2), 1e-2);
	EXPECT_NEAR(turned(2, 2), l(2, 2), 1e-6);
	EXPECT_NEAR(turned(0, 0), l(0, 0), 1e-6);
	EXPECT_NEAR(turned(4, 4), 2.0, 1e-9);
	EXPECT_NEAR(turned(3, 3), 4.0, 1e-9);
}

namespace
{
struct CorridorRun
{
	double error_x = 0;  ///< of the last frame along the corridor [m]
	int used = 0, dropped = 0;
};

/// LOAM on a VLP-16 between two smooth walls, 1 m per frame, the external motion each frame the
/// true one times `scale`, and `motion_sigma` (0: the motion only seeds the registration).
CorridorRun corridorDrive(double motion_sigma, double scale, double lateral = 0)
{
	const World corridor = corridorWorld(400, 4.0, 5.0);
	LoamOptions o = vlp16Options();
	o.prior.source = "external";
	o.prior.external_stage = "mapping";
	o.prior.check_deviation = 0;
	o.prior.motion_sigma = motion_sigma;
	LidarOdometry lo(o);
	const auto pose = [](int i) { return planarPose(20 + 1.0 * i, 0.3, 0) * Eigen::Translation3d(0, 0, 1.73); };
	CorridorRun out;
	for (int i = 0; i < 10; ++i)
	{
		std::optional<Eigen::Isometry3d> external;
		if (i > 0) external = planarPose(scale, lateral, 0);
		const LidarOdometryResult r = lo.process(0.1 * i, scan(corridor, vlp16(), pose(i)), external);
		out.error_x = r.pose.translation().x() - (pose(i).translation().x() - pose(0).translation().x());
		if (std::getenv("VLO_VERBOSE")) std::printf("%d: %s %s %s x %.4f cost %.3f\n", i, r.prior_source.c_str(), r.motion_prior.c_str(), toString(r.status), r.pose.translation().x(), r.motion_prior_cost);
		out.used += r.motion_prior == "used";
		out.dropped += r.motion_prior == "dropped";
	}
	return out;
}
}  // namespace

TEST(PosePrior, CarriesLoamAlongACorridorAsTheExternalMotionSays)
{
	// Along the corridor only the walls' noise constrains x: the rounds slide off the seed. With the
	// motion as a prior, x follows it, here 2 % long (0.18 m after 9 m) as a VO's scale might be.
	const CorridorRun seed = corridorDrive(0, 1.0), prior = corridorDrive(0.01, 1.0), long_prior = corridorDrive(0.01, 1.02);
	std::printf("corridor, 9 m: x error seeded only %.4f m, with the prior %.4f m, with a prior 2 %% long %.4f m (used %d)\n",
		seed.error_x, prior.error_x, long_prior.error_x, prior.used);
	EXPECT_EQ(prior.used, 9);
	EXPECT_LT(std::abs(prior.error_x), 0.01);
	EXPECT_NEAR(long_prior.error_x, 0.18, 0.03);
}

TEST(PosePrior, APriorThatPullsAgainstTheMapIsDropped)
{
	// 0.3 m sideways on every frame, where the walls fix y: the prior would drag them along, so
	// scan-to-map is solved again without it, and y stays the walls'.
	const CorridorRun r = corridorDrive(0.002, 1.0, 0.3);
	std::printf("prior 0.3 m sideways: dropped on %d of 9 frames\n", r.dropped);
	EXPECT_EQ(r.dropped, 9);
}
}  // namespace vlo::loam::test
