// The KITTI importers on the shared real data and on small constructed datasets.
#include "io_test_util.h"

#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>

#include <cmath>
#include <fstream>
#include <iostream>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
bool contains(const std::vector<std::string>& lines, const std::string& part)
{
	for (const auto& l : lines)
		if (l.find(part) != std::string::npos) return true;
	return false;
}

int rawlogEditInfo(const std::string& path)
{
	return std::system(("rawlog-edit --info -i '" + path + "' > '" + path + ".info.txt' 2>&1").c_str());
}

/// The import of sequence `seq` of the odometry layout at `root` into the rawlog `out`, camera 0.
KittiOdometryImport odometryImport(const std::string& root, const std::string& seq, const std::string& out)
{
	KittiOdometryImport opt;
	opt.root = root;
	opt.seq = seq;
	opt.out = out;
	return opt;
}

void expectSamePoses(const Trajectory& a, const Trajectory& b)
{
	ASSERT_EQ(a.size(), b.size());
	for (std::size_t k = 0; k < a.size(); ++k)
	{
		EXPECT_NEAR(a[k].t, b[k].t, 1e-9);
		EXPECT_LT((a[k].pose.matrix() - b[k].pose.matrix()).cwiseAbs().maxCoeff(), 2e-6) << "pose " << k;
	}
}
}  // namespace

TEST(KittiOdometryImport, RealSequence06IsCameraOnlyWithGroundTruth)
{
	const std::string root = sharedData("kitti_odometry_06_0000-0050"), dir = freshDir();
	KittiOdometryImport opt = odometryImport(root, "06", dir + "/s06.rawlog");
	const auto summary = importKittiOdometry(opt);
	EXPECT_EQ(summary.frames, 51u);
	EXPECT_EQ(summary.scans, 0u);
	EXPECT_TRUE(contains(summary.warnings, "camera-only"));
	EXPECT_TRUE(contains(summary.warnings, "without Tr"));
	EXPECT_EQ(summary.ground_truth, dir + "/s06.gt.tum");

	RawlogReaderOptions ro;
	ro.need_lidar = false;
	const auto frames = readFrames(opt.out, ro);
	const auto times = readKittiTimes(root + "/sequences/06/times.txt");
	ASSERT_EQ(frames.size(), 51u);
	ASSERT_EQ(times.size(), 51u);
	for (std::size_t k = 0; k < frames.size(); ++k) EXPECT_NEAR(frames[k].t, times[k], 1e-7) << k;
	EXPECT_EQ(frames[0].t, 0.0);
	EXPECT_EQ(frames[0].image.getWidth(), 1226u);
	EXPECT_EQ(frames[0].image.getHeight(), 370u);
	EXPECT_DOUBLE_EQ(frames[0].rig.camera.fx, 707.0912);
	EXPECT_DOUBLE_EQ(frames[0].rig.camera.cx, 601.8873);
	EXPECT_TRUE(frames[0].rig.vehicle_T_camera.isApprox(nominalCam0TVehicle().inverse(), 1e-12));

	const Trajectory gt = readTum(summary.ground_truth);
	const Trajectory expected = relativeToFirst(
		cameraToVehicle(readKittiPoses(root + "/poses/06.txt", times), nominalCam0TVehicle()));
	expectSamePoses(gt, expected);
	// Vehicle frame: KITTI 06 starts driving forward, i.e. along vehicle +x.
	EXPECT_GT(gt.back().pose.translation().x(), 5.0);
	EXPECT_EQ(rawlogEditInfo(opt.out), 0);
}

TEST(KittiOdometryImport, FrameRangeKeepsTheDatasetTimes)
{
	const std::string root = sharedData("kitti_odometry_06_0000-0050"), dir = freshDir();
	KittiOdometryImport opt = odometryImport(root, "06", dir + "/r.rawlog");
	opt.first = 10;
	opt.last = 20;
	EXPECT_EQ(importKittiOdometry(opt).frames, 11u);
	const auto times = readKittiTimes(root + "/sequences/06/times.txt");
	const Trajectory gt = readTum(dir + "/r.gt.tum");
	ASSERT_EQ(gt.size(), 11u);
	EXPECT_NEAR(gt.front().t, times[10], 1e-9);
	EXPECT_TRUE(gt.front().pose.isApprox(Eigen::Isometry3d::Identity(), 1e-12));
	RawlogReaderOptions ro;
	ro.need_lidar = false;
	const auto frames = readFrames(opt.out, ro);
	ASSERT_EQ(frames.size(), 11u);
	EXPECT_NEAR(frames.back().t, times[20], 1e-7);
	opt.first = 30;
	opt.last = 29;
	expectInputError([&] { importKittiOdometry(opt); }, {"bad frame range"});
}

TEST(KittiRawImport, RealSampleCamera2MatchesTheCalibrationProjection)
{
	const std::string drive = sharedData("kitti_raw_2011_09_26_sample"), dir = freshDir();
	KittiRawImport opt;
	opt.drive = opt.calib = drive;
	opt.out = dir + "/raw.rawlog";
	const auto summary = importKittiRaw(opt);
	EXPECT_EQ(summary.frames, 32u);
	EXPECT_EQ(summary.scans, 32u);
	EXPECT_TRUE(contains(summary.warnings, "10 Hz"));
	EXPECT_EQ(rawlogEditInfo(opt.out), 0);

	const auto frames = readFrames(opt.out);
	ASSERT_EQ(frames.size(), 32u);
	const auto calib =
		readKittiRawCalib(drive + "/calib_cam_to_cam.txt", drive + "/calib_velo_to_cam.txt", 2);
	const Matrix34d P = calib.projection();  // straight from the files
	for (std::size_t k = 0; k < frames.size(); k += 10)
	{
		const Frame& f = frames[k];
		EXPECT_NEAR(f.t, 0.1 * k, 1e-7);
		ASSERT_EQ(f.image.getWidth(), 1242u);
		ASSERT_EQ(f.image.getHeight(), 375u);
		EXPECT_FALSE(f.image.isColor());
		ASSERT_GT(f.scan.size(), 100000u);
		const Eigen::Isometry3d cam_T_lidar = f.rig.camera_T_lidar();
		const Eigen::Matrix3d K = f.rig.camera.K();
		std::size_t inside_rig = 0, inside_ref = 0;
		double max_err = 0;
		auto inside = [&](const Eigen::Vector3d& x) {
			return x.z() > 0 && x.x() / x.z() >= 0 && x.x() / x.z() < 1242 && x.y() / x.z() >= 0 && x.y() / x.z() < 375;
		};
		for (const auto& p : f.scan)
		{
			const Eigen::Vector3d X(p.x, p.y, p.z);
			const Eigen::Vector3d a = K * (cam_T_lidar * X), b = P * X.homogeneous();
			const bool ia = inside(a), ib = inside(b);
			inside_rig += ia;
			inside_ref += ib;
			if (ia && ib) max_err = std::max(max_err, (a.hnormalized() - b.hnormalized()).cwiseAbs().maxCoeff());
		}
		EXPECT_EQ(inside_rig, inside_ref) << "frame " << k;
		EXPECT_GT(inside_ref, f.scan.size() / 20) << "frame " << k;
		EXPECT_LT(max_err, 1e-3) << "frame " << k;
		std::cout << "frame " << k << ": " << inside_ref << " of " << f.scan.size()
				  << " points in the image, max difference " << max_err << " px\n";
	}

	// A real rawlog cut short is a clean error, wherever it is cut.
	std::ifstream in(opt.out, std::ios::binary);
	const std::string bytes((std::istreambuf_iterator<char>(in)), {});
	for (double frac : {0.5, 0.999})
	{
		const std::string cut = dir + "/cut.rawlog";
		std::ofstream(cut, std::ios::binary) << bytes.substr(0, static_cast<std::size_t>(frac * bytes.size()));
		if (!fs::exists(dir + "/cut_Images")) fs::create_directory_symlink(dir + "/raw_Images", dir + "/cut_Images");
		expectInputError([&] { readFrames(cut); }, {cut, "truncated"});
	}
}

TEST(KittiOdometryImport, ColourCamera2OfEverySnippetMatchesP2TimesTr)
{
	const std::string root = sharedData("kitti_odometry_snippets"), dir = freshDir();
	for (const std::string seq : {"00", "04", "06", "08"})
	{
		KittiOdometryImport opt = odometryImport(root, seq, dir + "/" + seq + ".rawlog");
		if (seq == "00") opt.camera = 2;  // the others by default: the snippets have image_2 only
		const auto summary = importKittiOdometry(opt);
		EXPECT_EQ(summary.frames, 10u);
		EXPECT_EQ(summary.scans, 10u);
		EXPECT_EQ(rawlogEditInfo(opt.out), 0);
		const auto calib = readKittiOdometryCalib(root + "/sequences/" + seq + "/calib.txt", 2);
		// The reference projection of a Velodyne point into image_2: P2 * Tr.
		Eigen::Matrix4d Tr = Eigen::Matrix4d::Identity();
		Tr.topRows<3>() = calib.cam0_T_velo.matrix().topRows<3>();
		const Matrix34d P = calib.P * Tr;
		const auto frames = readFrames(opt.out);
		ASSERT_EQ(frames.size(), 10u);
		const Frame& f = frames[5];
		EXPECT_FALSE(f.image.isColor());
		EXPECT_EQ(f.rig.camera.fx, calib.P(0, 0));
		const Eigen::Isometry3d cam_T_lidar = f.rig.camera_T_lidar();
		double max_err = 0;
		std::size_t inside = 0;
		for (const auto& p : f.scan)
		{
			const Eigen::Vector3d X(p.x, p.y, p.z);
			const Eigen::Vector3d a = f.rig.camera.K() * (cam_T_lidar * X), b = P * X.homogeneous();
			if (b.z() < 1) continue;
			const Eigen::Vector2d pb = b.hnormalized();
			if (pb.x() < 0 || pb.y() < 0 || pb.x() >= f.rig.camera.width || pb.y() >= f.rig.camera.height) continue;
			++inside;
			max_err = std::max(max_err, (a.hnormalized() - pb).cwiseAbs().maxCoeff());
		}
		EXPECT_GT(inside, f.scan.size() / 20) << seq;
		EXPECT_LT(max_err, 1e-6) << seq;  // camera 2 is 6 cm from camera 0: ~4 px at 10 m
		std::cout << seq << ": " << inside << " points in image_2, max difference " << max_err << " px\n";
	}
}
