// The "aloam" module as the run loop sees it: created by name, configured from an INI, given the
// vehicle's motion and returning the vehicle's pose, with the LiDAR mounted turned and offset on the
// vehicle. A 4.5 m, 12 deg jump defeats the constant-velocity guess; the vehicle motion given as the
// guess, moved into the LiDAR frame by the module, recovers it.
#include <gtest/gtest.h>
#include <vlo/kernel/lidar_odometry.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "../synthetic_world.h"
#include "../test_helpers.h"

namespace vlo::loam::test
{
namespace
{
struct Drive
{
	Frame a, b;
	Eigen::Isometry3d vehicle_motion;  ///< pose of the vehicle at b in the vehicle at a
};

/// Two scans of an urban world; the LiDAR looks to the vehicle's left, 0.5 m ahead, 1.8 m up.
Drive drive()
{
	Path path;
	path.add(80, 0.0);
	const World w = urbanWorld(path, 9);
	LidarModel m = hdl64();
	m.noise_sigma = 0.01;
	std::mt19937 rng(9);
	const Eigen::Isometry3d Tvl = planarPose(0.5, 0.2, 90) * Eigen::Translation3d(0, 0, 1.8);
	const Eigen::Isometry3d lidarMotion = planarPose(4.5, 0.4, 12);  // along the street, the LiDAR's x
	const Eigen::Isometry3d A = lidarPoseAt(path, 25);
	Drive d;
	for (Frame* f : {&d.a, &d.b})
	{
		f->has_scan = true;
		f->rig.has_lidar = true;
		f->rig.vehicle_T_lidar = Tvl;
	}
	d.a.scan = scan(w, m, A, &rng);
	d.b.scan = scan(w, m, A * lidarMotion, &rng);
	d.b.index = 1;
	d.b.t = 0.1;
	d.vehicle_motion = Tvl * lidarMotion * Tvl.inverse();
	return d;
}

/// The module's steps at both frames, and the prior it says it used at the second; its frames.csv rows
/// in `out` if given.
std::tuple<kernel::LidarOdometryStep, kernel::LidarOdometryStep, std::string> steps(const Drive& d,
	const std::optional<Eigen::Isometry3d>& guess, const std::vector<std::string>& sets = {},
	kernel::FrameTable* out = nullptr)
{
	auto config = kernel::RunConfig::fromString("[loam.scan]\nring_model = hdl64\n", "test.ini", sets);
	auto lo = kernel::registry<kernel::LidarOdometryModule>().create("aloam", "test");
	lo->configure(config);
	config.checkAllKeysUsed();
	kernel::FrameTable table;
	table.newRow();
	kernel::LidarOdometryStep first = lo->process(d.a, nullptr, std::nullopt, table);
	table.newRow();
	std::optional<kernel::MotionGuess> g;
	if (guess) g = kernel::MotionGuess{*guess, {50, std::nan("")}};
	kernel::LidarOdometryStep second = lo->process(d.b, nullptr, g, table);
	if (out) *out = table;
	return {first, second, table.cell(1, "lo_prior")};
}

/// The module's vehicle pose at the second frame, and the prior it says it used.
std::pair<Eigen::Isometry3d, std::string> run(const Drive& d, const std::optional<Eigen::Isometry3d>& guess,
	const std::vector<std::string>& sets = {}, kernel::FrameTable* out = nullptr)
{
	const auto [first, second, prior] = steps(d, guess, sets, out);
	return {second.pose, prior};
}
}  // namespace

TEST(AloamModule, TakesTheVehicleMotionAsGuessAndReturnsTheVehiclePose)
{
	const Drive d = drive();
	const Eigen::Isometry3d guess = d.vehicle_motion * planarPose(0.1, -0.05, 0.5);  // VO-like error
	const auto [pose, prior] = run(d, guess);
	EXPECT_EQ(prior, "external");
	EXPECT_LT(translationError(pose, d.vehicle_motion), 0.01);
	EXPECT_LT(rotationErrorDeg(pose, d.vehicle_motion), 0.05);
}

TEST(AloamModule, WithoutGuessOrWithConstantVelocityTheJumpIsMissed)
{
	// With A-LOAM's own two scan-to-scan rounds and no search of the first motion (the defaults iterate
	// until converged and search the first motion: they would catch even this jump, doc/LOAM.md "Cold
	// start"), which prior the adapter passed decides the result.
	const Drive d = drive();
	const std::string two = "loam.odometry.max_rounds=2", zero = "loam.odometry.cold_start_range=0";
	const auto [none, priorNone] = run(d, std::nullopt, {two, zero});
	EXPECT_EQ(priorNone, "constant_velocity");
	EXPECT_GT(translationError(none, d.vehicle_motion), 0.05);
	const auto [cv, priorCv] = run(d, d.vehicle_motion, {"loam.prior.source=constant_velocity", two, zero});
	EXPECT_EQ(priorCv, "constant_velocity");  // told to ignore guesses
	EXPECT_GT(translationError(cv, d.vehicle_motion), 0.05);
}

TEST(AloamModule, SaysHowTheGuessWeighedInScanToMap)
{
	// The guess is also a residual of scan-to-map, its information from the source's quality: 0.02 m
	// against matches of the loss scale 0.05 m is 6.25 matches' worth per axis, and 50 features
	// tracked of full_quality_tracked 100 halve it.
	const Drive d = drive();
	kernel::FrameTable with, without;
	run(d, d.vehicle_motion, {"loam.prior.motion_sigma=0.02"}, &with);
	EXPECT_EQ(with.cell(1, "lo_motion_prior"), "used");
	EXPECT_EQ(with.cell(1, "lo_motion_prior_info"), "3.1");
	// Without a guess (mode lo) the columns do not exist: its frames.csv is what it was.
	run(d, std::nullopt, {"loam.prior.motion_sigma=0.02"}, &without);
	const std::vector<std::string> columns = without.columns();
	EXPECT_EQ(std::count(columns.begin(), columns.end(), "lo_motion_prior"), 0);
}

TEST(AloamModule, GivesTheRegistrationsInformationOverTheVehiclesMotion)
{
	// The street runs along the LiDAR's x, the vehicle's y: scan-to-map knows the position least along
	// it, and so does the information the module gives, in the vehicle's frame.
	const Drive d = drive();
	const auto [first, second, prior] = steps(d, d.vehicle_motion);
	EXPECT_FALSE(first.information.has_value());  // nothing to register against
	ASSERT_TRUE(second.information.has_value());
	const Matrix6d cov = invertPositive(*second.information);
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov.topLeftCorner<3, 3>());
	const Eigen::Vector3d weakest = es.eigenvectors().col(2);
	std::printf("sigma x %.4f y %.4f z %.4f m, yaw %.4f deg, weakest (%.2f %.2f %.2f)\n", std::sqrt(cov(0, 0)),
		std::sqrt(cov(1, 1)), std::sqrt(cov(2, 2)), std::sqrt(cov(5, 5)) * 180 / M_PI, weakest.x(), weakest.y(), weakest.z());
	EXPECT_GT(std::abs(weakest.y()), 0.9);
	// 100 effective points at the scan's 1 cm or more: millimetres to centimetres, never metres.
	EXPECT_GT(std::sqrt(cov(1, 1)), 5e-4);
	EXPECT_LT(std::sqrt(cov(1, 1)), 0.05);
	EXPECT_LT(std::sqrt(cov(5, 5)) * 180 / M_PI, 0.5);
}
}  // namespace vlo::loam::test
