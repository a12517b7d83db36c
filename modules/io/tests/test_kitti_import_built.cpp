// The KITTI importers on small datasets built here: LiDAR with Tr, raw timestamps, and bad input
// that must fail with one clear message and leave no output behind.
#include "io_test_util.h"

#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
const char* kTr = "Tr: 0 -1 0 0.1 0 0 -1 -0.2 1 0 0 -0.3\n";

/// sequences/00 with 3 frames (40x30 images, 5-point scans), calib.txt with Tr, times, poses.
std::string buildOdometry(const std::string& root)
{
	const std::string seq = root + "/sequences/00";
	fs::create_directories(seq + "/image_0");
	fs::create_directories(seq + "/velodyne");
	fs::create_directories(root + "/poses");
	std::ofstream(seq + "/calib.txt") << "P0: 50 0 20 0 0 50 15 0 0 0 1 0\n"
									  << kTr;
	std::ofstream(seq + "/times.txt") << "0.000000e+00\n1.000000e-01\n2.000000e-01\n";
	std::ofstream(root + "/poses/00.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 1\n1 0 0 0 0 1 0 0 0 0 1 2\n";
	for (int k = 0; k < 3; ++k)
	{
		char name[16];
		std::snprintf(name, sizeof(name), "%06d", k);
		testFrame(k, 0, 40, 30).image.saveToFile(seq + "/image_0/" + name + ".png");
		writeKittiBin(seq + "/velodyne/" + std::string(name) + ".bin", {{1, 2, 3, 0.5f}, {4, 5, 6, 0}, {7, 8, 9, 1}, {10, 0, 1, 0}, {0, 10, 1, 0}});
	}
	return seq;
}

KittiOdometryImport options(const std::string& root)
{
	KittiOdometryImport opt;
	opt.root = root;
	opt.seq = "00";
	opt.out = root + "/out/x.rawlog";
	return opt;
}

void expectNoOutput(const std::string& root)
{
	for (const char* f : {"x.rawlog", "x.rawlog.partial", "x_Images", "x_Images.partial", "x.gt.tum"})
		EXPECT_FALSE(fs::exists(root + "/out/" + f)) << f << " left behind";
}
}  // namespace

TEST(KittiOdometryBuilt, VelodyneAndTrGiveTheRigAndVehicleGroundTruth)
{
	const std::string root = freshDir();
	buildOdometry(root);
	const auto summary = importKittiOdometry(options(root));
	EXPECT_EQ(summary.frames, 3u);
	EXPECT_EQ(summary.scans, 3u);
	EXPECT_TRUE(summary.warnings.empty()) << summary.warnings.front();

	const auto calib = readKittiOdometryCalib(root + "/sequences/00/calib.txt");
	RawlogReader reader(root + "/out/x.rawlog");
	Frame f;
	std::size_t n = 0;
	while (reader.next(f))
	{
		EXPECT_NEAR(f.t, 0.1 * n++, 1e-9);
		EXPECT_EQ(f.scan.size(), 5u);
		EXPECT_TRUE(f.rig.vehicle_T_camera.isApprox(calib.cam0_T_velo.inverse(), 1e-12));
		EXPECT_TRUE(f.rig.vehicle_T_lidar.isApprox(Eigen::Isometry3d::Identity()));
		EXPECT_EQ(f.rig.camera.width, 40);
	}
	EXPECT_EQ(n, 3u);
	// Camera 0 moves 1 m along its z per frame: that is +1 m along vehicle x.
	const Trajectory gt = readTum(root + "/out/x.gt.tum");
	ASSERT_EQ(gt.size(), 3u);
	EXPECT_TRUE(gt[2].pose.translation().isApprox(Eigen::Vector3d(2, 0, 0), 1e-12));
}

TEST(KittiOdometryBuilt, BadInputFailsNamingTheFileAndLeavesNoOutput)
{
	const std::string root = freshDir();
	const std::string seq = buildOdometry(root);
	const auto opt = options(root);

	std::ofstream(seq + "/velodyne/000001.bin", std::ios::app) << "x";  // 81 bytes
	expectInputError([&] { importKittiOdometry(opt); }, {seq + "/velodyne/000001.bin", "not a multiple of 16"});
	expectNoOutput(root);
	writeKittiBin(seq + "/velodyne/000001.bin", {{1, 2, 3, 0}});

	std::ofstream(seq + "/times.txt") << "0.0\n0.2\n0.1\n";
	expectInputError([&] { importKittiOdometry(opt); }, {seq + "/times.txt", "line 3"});
	expectNoOutput(root);
	std::ofstream(seq + "/times.txt") << "0.0\n0.1\n";
	expectInputError([&] { importKittiOdometry(opt); }, {seq + "/times.txt", "has 2 times"});
	std::ofstream(seq + "/times.txt") << "0.0\n0.1\n0.2\n";

	std::ofstream(root + "/poses/00.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 nan 0 0 1 1\n";
	expectInputError([&] { importKittiOdometry(opt); }, {root + "/poses/00.txt", "line 2"});
	expectNoOutput(root);
	fs::remove(root + "/poses/00.txt");

	std::ofstream(seq + "/calib.txt") << kTr;
	expectInputError([&] { importKittiOdometry(opt); }, {seq + "/calib.txt", "missing key 'P0'"});
	std::ofstream(seq + "/calib.txt") << "P0: 50 0 20 0 0 50 15 0 0 0 1 0\n"
									  << kTr;

	fs::rename(seq + "/image_0", seq + "/image_x");
	expectInputError([&] { importKittiOdometry(opt); }, {seq + "/image_0", "directory not found"});
	expectNoOutput(root);
	// Issue 34, defect 8: colour-only data (image_2) got no hint about --camera. By default it is now
	// imported from camera 2 (whose P2 this calib.txt lacks); camera 0 asked for gets the hint.
	fs::rename(seq + "/image_x", seq + "/image_2");
	expectInputError([&] { importKittiOdometry(opt); }, {seq + "/calib.txt", "missing key 'P2'"});
	KittiOdometryImport grey = opt;
	grey.camera = 0;
	expectInputError([&] { importKittiOdometry(grey); }, {seq + "/image_0: directory not found (this sequence has image_2: give --camera 2)"});
	fs::rename(seq + "/image_2", seq + "/image_0");

	// NaN points are dropped with a warning naming the file, not an error.
	const float nan = std::numeric_limits<float>::quiet_NaN();
	writeKittiBin(seq + "/velodyne/000002.bin", {{1, 2, 3, 0}, {nan, nan, nan, 0}, {1, nan, 1, 0}});
	const auto summary = importKittiOdometry(opt);
	EXPECT_EQ(summary.invalid_points, 2u);
	ASSERT_FALSE(summary.warnings.empty());
	EXPECT_NE(summary.warnings.back().find(seq + "/velodyne/000002.bin: 2 non-finite points dropped"), std::string::npos)
		<< summary.warnings.back();
	EXPECT_TRUE(summary.ground_truth.empty());  // poses/00.txt was removed above

	// A scan with no valid point at all is corrupt: an error naming it, and no output.
	writeKittiBin(seq + "/velodyne/000002.bin", {{nan, nan, nan, 0}, {1, nan, 1, 0}});
	fs::remove_all(root + "/out");
	expectInputError([&] { importKittiOdometry(opt); }, {seq + "/velodyne/000002.bin", "every point is NaN"});
	writeKittiBin(seq + "/velodyne/000002.bin", {});
	expectInputError([&] { importKittiOdometry(opt); }, {seq + "/velodyne/000002.bin", "empty scan"});
}

TEST(KittiRawBuilt, TimestampsOfEachSensorAreUsed)
{
	const std::string drive = freshDir(), raw = sharedData("kitti_raw_2011_09_26_sample");
	fs::create_directories(drive + "/image_00/data");
	fs::create_directories(drive + "/velodyne_points/data");
	for (int k = 0; k < 3; ++k)
	{
		char name[16];
		std::snprintf(name, sizeof(name), "%010d", k);
		testFrame(k, 0, 1242, 375).image.saveToFile(drive + "/image_00/data/" + name + ".png");
		writeKittiBin(drive + "/velodyne_points/data/" + std::string(name) + ".bin", {{5, 0, 0, 0}});
	}
	std::ofstream(drive + "/image_00/timestamps.txt")
		<< "2011-09-26 13:02:25.964389445\n2011-09-26 13:02:26.068749856\n2011-09-26 13:02:26.173079061\n";
	std::ofstream(drive + "/velodyne_points/timestamps.txt")
		<< "2011-09-26 13:02:25.951199\n2011-09-26 13:02:26.054651\n2011-09-26 13:02:26.158214\n";
	// Each sweep from 52 ms before its stamp to 52 ms after (the stamp: facing forward, half-way).
	std::ofstream(drive + "/velodyne_points/timestamps_start.txt")
		<< "2011-09-26 13:02:25.899199\n2011-09-26 13:02:26.002651\n2011-09-26 13:02:26.106214\n";
	std::ofstream(drive + "/velodyne_points/timestamps_end.txt")
		<< "2011-09-26 13:02:26.003199\n2011-09-26 13:02:26.106651\n2011-09-26 13:02:26.210214\n";
	KittiRawImport opt;
	opt.drive = drive;
	opt.calib = raw;
	opt.camera = 0;
	opt.out = drive + "/out.rawlog";
	const auto summary = importKittiRaw(opt);
	EXPECT_EQ(summary.frames, 3u);
	EXPECT_TRUE(summary.warnings.empty());

	RawlogReader reader(opt.out);
	Frame f;
	ASSERT_TRUE(reader.next(f));
	EXPECT_NEAR(f.t, 1317042145.964389445, 1e-6);  // a pair carries the image time
	// The one return, straight ahead, was taken at the scan's stamp: 13.19 ms before the image.
	ASSERT_TRUE(f.scan.has_time);
	EXPECT_NEAR(f.scan[0].time, 25.951199 - 25.964389445, 2e-6);
	EXPECT_NEAR(f.rig.camera.fx, 721.5377, 1e-9);
	EXPECT_EQ(reader.stats().unpaired_images + reader.stats().unpaired_scans, 0u);

	fs::remove(drive + "/velodyne_points/timestamps.txt");  // LiDAR borrows the camera's times
	const auto borrowed = importKittiRaw(opt);  // and without its own stamp no sweep can be timed
	ASSERT_EQ(borrowed.warnings.size(), 1u);
	EXPECT_NE(borrowed.warnings[0].find("without point times"), std::string::npos) << borrowed.warnings[0];
	RawlogReader again(opt.out);
	std::size_t n = 0;
	while (again.next(f))
	{
		EXPECT_FALSE(f.scan.has_time);
		++n;
	}
	EXPECT_EQ(n, 3u);

	opt.camera = 1;  // no image_01
	expectInputError([&] { importKittiRaw(opt); }, {drive + "/image_01/data", "directory not found"});
	opt.camera = 5;
	expectInputError([&] { importKittiRaw(opt); }, {"--camera", "0, 1, 2 or 3"});
}

// oxts/ gives both truths: the positions' (X.gt.tum) and the velocities' (X.gt_velocity.tum); records
// without velocities give the first and a warning.
TEST(KittiRawBuilt, OxtsRecordsGiveThePositionsAndTheVelocitiesTruths)
{
	const std::string drive = freshDir(), raw = sharedData("kitti_raw_2011_09_26_sample");
	fs::create_directories(drive + "/image_00/data");
	fs::create_directories(drive + "/oxts/data");
	std::ofstream(drive + "/image_00/timestamps.txt") << "2011-09-26 13:02:26.0\n2011-09-26 13:02:26.1\n2011-09-26 13:02:26.2\n";
	std::ofstream(drive + "/oxts/timestamps.txt") << "2011-09-26 13:02:26.0\n2011-09-26 13:02:26.1\n2011-09-26 13:02:26.2\n";
	// Due north at 10 m/s (vn = 10), level, facing north; the positions say 1.01 m a step.
	const auto record = [&](int k, bool velocity) {
		char name[16];
		std::snprintf(name, sizeof(name), "%010d", k);
		std::ofstream f(drive + "/oxts/data/" + name + ".txt");
		f << std::setprecision(12) << 49.0 + k * 1.01 / 111200.0 << " 8.4 100 0 0 " << M_PI / 2;
		if (velocity) f << " 10 0 10 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0.15 0.03 4 8 4 4 4";
		f << "\n";
	};
	for (int k = 0; k < 3; ++k)
	{
		char name[16];
		std::snprintf(name, sizeof(name), "%010d", k);
		testFrame(k, 0, 1242, 375).image.saveToFile(drive + "/image_00/data/" + name + ".png");
		record(k, true);
	}
	KittiRawImport opt;
	opt.drive = drive, opt.calib = raw, opt.camera = 0, opt.out = drive + "/out.rawlog";
	const auto summary = importKittiRaw(opt);
	EXPECT_EQ(summary.ground_truth, drive + "/out.gt.tum");
	ASSERT_EQ(summary.velocity_truth, drive + "/out.gt_velocity.tum");
	const Trajectory pos = readTum(summary.ground_truth), vel = readTum(summary.velocity_truth);
	ASSERT_EQ(vel.size(), 3u);
	EXPECT_NEAR(pathLength(pos), 2.02, 0.02);
	EXPECT_NEAR(pathLength(vel), 2.0, 1e-5);  // 10 m/s for 0.2 s, whatever frame it is drawn in
	EXPECT_NEAR(vel[2].t - vel[0].t, 0.2, 1e-6);

	record(1, false);  // a record cut after the orientation
	fs::remove(summary.velocity_truth);
	const auto without = importKittiRaw(opt);
	EXPECT_TRUE(without.velocity_truth.empty());
	EXPECT_FALSE(fs::exists(drive + "/out.gt_velocity.tum"));
	EXPECT_EQ(readTum(without.ground_truth).size(), 3u);
	ASSERT_FALSE(without.warnings.empty());
	EXPECT_NE(without.warnings.back().find("records without velocities"), std::string::npos) << without.warnings.back();
}

// Issue 34, defect 3: a frame whose image is missing was dropped without a word (a missing scan warned),
// and --last beyond the data was clamped silently.
TEST(KittiOdometryBuilt, AFrameWithoutItsImageIsSaidAndKeepsItsScan)
{
	const std::string root = freshDir();
	const std::string seq = buildOdometry(root);
	fs::remove(seq + "/image_0/000001.png");
	auto opt = options(root);
	opt.last = 7;
	const auto summary = importKittiOdometry(opt);
	EXPECT_EQ(summary.frames, 3u);
	EXPECT_EQ(summary.images, 2u);
	EXPECT_EQ(summary.scans, 3u);
	ASSERT_EQ(summary.warnings.size(), 2u);
	EXPECT_NE(summary.warnings[0].find("--last 7: " + seq + " ends at frame 2"), std::string::npos) << summary.warnings[0];
	EXPECT_NE(summary.warnings[1].find(seq + "/image_0: no image for 1 frame (the first: frame 1)"), std::string::npos)
		<< summary.warnings[1];

	fs::remove(seq + "/velodyne/000001.bin");  // frame 1 now has nothing: skipped
	fs::remove_all(root + "/out");
	const auto again = importKittiOdometry(options(root));
	EXPECT_EQ(again.frames, 2u);
	EXPECT_EQ(again.images, 2u);
	EXPECT_EQ(again.scans, 2u);
	ASSERT_EQ(again.warnings.size(), 2u);
	EXPECT_NE(again.warnings[0].find("no image for 1 frame (the first: frame 1); their scans are imported"),
		std::string::npos)
		<< again.warnings[0];
	EXPECT_NE(again.warnings[1].find(seq + "/velodyne: no scan for 1 frame (the first: frame 1)"), std::string::npos)
		<< again.warnings[1];
}
