// KITTI raw drive 2011_09_26_0013, frames 0-47 (../shared/data): the raw sweeps at 11-13 m/s with their
// start and end stamps, and the OXTS ground truth.
#include "io_test_util.h"

#include <vlo/core/sweep_times.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/kitti_oxts.h>
#include <vlo/io/trajectory.h>

#include <algorithm>
#include <cmath>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
const char* kDrive = "kitti_raw_2011_09_26_drive_0013_0000-0047";

/// The drive imported once for all tests of this file.
const std::string& importedDrive()
{
	static const std::string rawlog = [] {
		const std::string root = sharedData(kDrive), dir = freshDir();
		KittiRawImport opt;
		opt.drive = root + "/2011_09_26_drive_0013_sync";
		opt.calib = root;
		opt.out = dir + "/d13.rawlog";
		const ImportSummary s = importKittiRaw(opt);
		EXPECT_EQ(s.frames, 48u);
		EXPECT_EQ(s.ground_truth, dir + "/d13.gt.tum");
		return opt.out;
	}();
	return rawlog;
}
}  // namespace

TEST(KittiOxts, MercatorScaledByTheFirstLatitudeAndYawPitchRoll)
{
	// 0.001 deg of longitude east at 49 deg north: R pi/180 cos(49 deg) 1e-3 = 73.05 m along x;
	// 0.001 deg of latitude north: the Mercator y grows by R ln(tan) differences, 111.3 m scaled by
	// cos(49 deg) / cos(49.001 deg) ~ 111.32 m.
	const double R = 6378137.0, lat = 49.0, s = std::cos(lat * M_PI / 180);
	OxtsRecord a{lat, 8.4, 100.0, 0.0, 0.0, 0.3};
	OxtsRecord east = a, north = a, turned = a;
	east.lon += 1e-3;
	north.lat += 1e-3;
	north.alt += 2.0;
	turned.roll = 0.02, turned.pitch = -0.01, turned.yaw = 0.5;
	const auto poses = oxtsPoses({a, east, north, turned});
	ASSERT_EQ(poses.size(), 4u);
	EXPECT_TRUE(poses[0].isApprox(Eigen::Isometry3d::Identity(), 1e-12));
	// Relative to the first record, which faces yaw 0.3: world offsets turned into its frame.
	const Eigen::Matrix3d first = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	const Eigen::Vector3d east_world(s * R * M_PI / 180 * 1e-3, 0, 0);
	EXPECT_LT((poses[1].translation() - first.transpose() * east_world).norm(), 1e-6);
	const double dy = s * R * (std::log(std::tan((90 + lat + 1e-3) * M_PI / 360)) - std::log(std::tan((90 + lat) * M_PI / 360)));
	EXPECT_NEAR(dy, 111.32, 0.05);
	EXPECT_LT((poses[2].translation() - first.transpose() * Eigen::Vector3d(0, dy, 2.0)).norm(), 1e-6);
	const Eigen::Matrix3d Rt = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-0.01, Eigen::Vector3d::UnitY()) *
		Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitX()))
								   .toRotationMatrix();
	EXPECT_LT((poses[3].linear() - first.transpose() * Rt).norm(), 1e-12);
}

TEST(KittiOxts, DeadReckonedFromTheVelocitiesByTrapezoids)
{
	// East at 10 m/s, then accelerating north; the first record faces yaw 0.3, so the positions are
	// turned into its frame. Times 0, 0.1, 0.3.
	OxtsRecord a{49.0, 8.4, 100.0, 0.0, 0.0, 0.3, 0.0, 10.0, 0.0, true};
	OxtsRecord b = a, c = a;
	b.vn = 2.0, b.vu = 1.0;
	c.vn = 4.0, c.vu = 1.0, c.yaw = 0.5;
	const auto poses = oxtsDeadReckonedPoses({a, b, c}, {0.0, 0.1, 0.3});
	ASSERT_EQ(poses.size(), 3u);
	const Eigen::Matrix3d first = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	// 0.1 s at (10, 0, 0) -> (10, 2, 1): (1.0, 0.1, 0.05); then 0.2 s at (10, 2, 1) -> (10, 4, 1): (2.0, 0.6, 0.2).
	EXPECT_LT((poses[1].translation() - first.transpose() * Eigen::Vector3d(1.0, 0.1, 0.05)).norm(), 1e-12);
	EXPECT_LT((poses[2].translation() - first.transpose() * Eigen::Vector3d(3.0, 0.7, 0.25)).norm(), 1e-12);
	EXPECT_LT((poses[2].linear() - oxtsPoses({a, b, c})[2].linear()).norm(), 1e-12);  // the same orientations
	c.has_velocity = false;
	EXPECT_TRUE(oxtsDeadReckonedPoses({a, b, c}, {0.0, 0.1, 0.3}).empty());
	EXPECT_TRUE(oxtsDeadReckonedPoses({a, b}, {0.1, 0.1}).empty());  // no time passes
}

// Drive 0013's positions (differential GPS, 0.15 m) and its velocities (0.03 m/s) agree on the length
// of frames 0-29 and part after: the positions make frames 29-47 1 % longer (doc/EVALUATION.md).
TEST(KittiRawDrive, TheVelocitiesMeasureTheLengthWhereThePositionsWander)
{
	const Trajectory pos = readTum(groundTruthPathFor(importedDrive()));
	const Trajectory vel = readTum(velocityTruthPathFor(importedDrive()));
	ASSERT_EQ(vel.size(), 48u);
	EXPECT_TRUE(vel.front().pose.isApprox(Eigen::Isometry3d::Identity(), 1e-9));
	const auto length = [](const Trajectory& t, std::size_t a, std::size_t b) {
		return pathLength(Trajectory(t.begin() + static_cast<long>(a), t.begin() + static_cast<long>(b) + 1));
	};
	EXPECT_NEAR(length(pos, 0, 29) / length(vel, 0, 29), 1.0, 0.001);
	EXPECT_NEAR(length(pos, 29, 47) / length(vel, 29, 47), 1.010, 0.002);
	EXPECT_NEAR(pathLength(pos) / pathLength(vel), 1.0038, 0.001);
	// Each step of the velocities' track is smooth: 11.7-10.7 m/s without the positions' jumps.
	for (std::size_t i = 1; i < vel.size(); ++i)
	{
		const double v = (vel[i].pose.translation() - vel[i - 1].pose.translation()).norm() / (vel[i].t - vel[i - 1].t);
		EXPECT_GT(v, 10.6) << i;
		EXPECT_LT(v, 11.9) << i;
	}
}

TEST(KittiRawDrive, GroundTruthIsTheDevkitsPoseInTheVelodyneFrame)
{
	const Trajectory gt = readTum(groundTruthPathFor(importedDrive()));
	ASSERT_EQ(gt.size(), 48u);
	EXPECT_TRUE(gt.front().pose.isApprox(Eigen::Isometry3d::Identity(), 1e-9));
	// oxts/timestamps.txt: 2011-09-26 13:10:51.175862102 and 13:10:55.965...
	EXPECT_NEAR(gt.front().t, 1317042651.175862, 1e-5);
	// The devkit's convertOxtsToPose conjugated by calib_imu_to_velo.txt, computed independently
	// (numpy): frames 1 and 47.
	EXPECT_LT((gt[1].pose.translation() - Eigen::Vector3d(1.179778, -0.005093, 0.014437)).norm(), 1e-5);
	EXPECT_LT((gt[47].pose.translation() - Eigen::Vector3d(54.288927, -0.275808, 1.122380)).norm(), 1e-5);
	const Eigen::Quaterniond q47(gt[47].pose.linear());
	EXPECT_LT((q47.coeffs() - Eigen::Vector4d(0.007520950, -0.003391427, -0.009110492, 0.999924463)).norm(), 1e-7);
	EXPECT_NEAR(pathLength(gt), 54.3, 0.2);
}

TEST(KittiRawDrive, SweepTimesFromTheStampsAreTheAzimuthRuleOfTheForwardFacingFrame)
{
	// The importer times each return from its azimuth, the sweep's start and end stamps and the scan's
	// stamp; the [lidar] default rule (a 0.1 s clockwise turn, forward at the frame's time) must give
	// nearly the same times, since KITTI stamps its scans as the laser faces forward, half-way.
	RawlogReader reader(importedDrive().c_str());
	Frame f;
	std::size_t frames = 0;
	double worst = 0, lo = 0, hi = 0;
	const SpinningSweep rule;
	while (reader.next(f))
	{
		ASSERT_TRUE(f.scan.has_time) << "frame " << frames;
		// The frame's time is the camera's, 8-14 ms after the scan's stamp: the times count from it.
		double offset = 0;
		for (const LidarPoint& p : f.scan)
			if (std::fabs(std::atan2(p.y, p.x)) < 1e-3) offset = p.time;
		EXPECT_LT(offset, -0.005) << "frame " << frames;
		EXPECT_GT(offset, -0.02) << "frame " << frames;
		for (const LidarPoint& p : f.scan)
		{
			const double t = p.time - offset, az = std::atan2(p.y, p.x);
			lo = std::min(lo, t), hi = std::max(hi, t);
			if (std::fabs(std::fabs(az) - M_PI) > 0.01)  // away from the seam, where either end is right
				worst = std::max(worst, std::fabs(t - rule.timeAt(az)));
		}
		++frames;
	}
	EXPECT_EQ(frames, 48u);
	EXPECT_LT(worst, 0.002);  // the real turn lasts 103.5 ms, not 100: 1.75 ms at the ends
	EXPECT_NEAR(lo, -0.0518, 0.001);
	EXPECT_NEAR(hi, 0.0518, 0.001);
}
