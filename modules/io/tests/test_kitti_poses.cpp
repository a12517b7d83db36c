// KITTI poses out and back in: vehicle-frame trajectories <-> the devkit's camera-0 poses, and the note of
// camera 0 that KITTI imports leave in the rawlog.
#include "io_test_util.h"

#include <vlo/io/frame_observations.h>
#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/trajectory.h>

#include <fstream>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
/// Tr (Velodyne -> camera 0) of KITTI odometry sequence 00, as its calib.txt prints it.
Eigen::Isometry3d tr00()
{
	return rigidFromText("4.276802385584e-04 -9.999672484946e-01 -8.084491683471e-03 -1.198459927713e-02 "
						 "-7.210626507497e-03 8.081198471645e-03 -9.999413164504e-01 -5.403984729748e-02 "
						 "9.999738645903e-01 4.859485810390e-04 -7.206933692422e-03 -2.921968648686e-01",
		"Tr of sequence 00");
}

/// 50 poses 0.1 s apart: 10 m/s forward on a 100 m radius left turn, climbing 1 %, rolling 2 degrees.
Trajectory curvedDrive()
{
	Trajectory t;
	for (int k = 0; k < 50; ++k)
	{
		const double s = 1.0 * k, yaw = s / 100.0;
		StampedPose p;
		p.t = 1000.0 + 0.1 * k;
		p.pose.translation() = Eigen::Vector3d(100 * std::sin(yaw), 100 * (1 - std::cos(yaw)), 0.01 * s);
		p.pose.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
			Eigen::AngleAxisd(0.035 * std::sin(0.2 * k), Eigen::Vector3d::UnitX()))
							  .toRotationMatrix();
		t.push_back(p);
	}
	return t;
}

double largestDifference(const Trajectory& a, const Trajectory& b)
{
	EXPECT_EQ(a.size(), b.size());
	double d = 0;
	for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
		d = std::max(d, (a[k].pose.matrix() - b[k].pose.matrix()).cwiseAbs().maxCoeff());
	return d;
}
}  // namespace

TEST(KittiPoses, TumToKittiToTumRoundTripUnderSequence00sCalib)
{
	const std::string dir = freshDir();
	const Eigen::Isometry3d Tr = tr00();
	writeTum(dir + "/drive.tum", curvedDrive());
	const Trajectory vehicle = readTum(dir + "/drive.tum");
	writeKittiPoses(dir + "/drive.kitti.txt", vehicleToCamera(vehicle, Tr));
	EXPECT_EQ(trajectoryFormatOf(dir + "/drive.tum"), TrajectoryFormat::Tum);
	EXPECT_EQ(trajectoryFormatOf(dir + "/drive.kitti.txt"), TrajectoryFormat::Kitti);

	std::vector<double> times;
	for (const auto& p : vehicle) times.push_back(p.t);
	const Trajectory camera = readKittiPoses(dir + "/drive.kitti.txt", times);
	// Camera 0 looks forward (z), to the right (x) and down (y): 47 m of driving, 11.8 m to the left, 0.5 m up,
	// give or take Tr's 0.4 deg tilt (0.34 m over 47 m) and its 0.3 m lever arm turned by the turn (0.14 m).
	const Eigen::Vector3d last = camera.back().pose.translation(), v = vehicle.back().pose.translation();
	EXPECT_GT(v.y(), 11.0);
	EXPECT_NEAR(last.z(), v.x(), 0.5);
	EXPECT_NEAR(last.x(), -v.y(), 0.5);
	EXPECT_NEAR(last.y(), -v.z(), 0.5);
	EXPECT_LT((camera.front().pose.matrix() - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff(), 1e-12);

	writeTum(dir + "/back.tum", cameraToVehicle(camera, Tr));
	const Trajectory back = readTum(dir + "/back.tum");
	EXPECT_LT(largestDifference(back, vehicle), 1e-6);  // 9 significant digits in each file
	for (std::size_t k = 0; k < back.size(); ++k) EXPECT_DOUBLE_EQ(back[k].t, vehicle[k].t);
}

TEST(KittiPoses, SnippetGroundTruthSurvivesTheVehicleFrameUnchanged)
{
	const std::string root = sharedData("kitti_odometry_snippets"), dir = freshDir();
	const std::string seq = root + "/sequences/00";
	const Eigen::Isometry3d Tr = readKittiOdometryCalib(seq + "/calib.txt").cam0_T_velo;
	const Trajectory devkit = readKittiPoses(root + "/poses/00.txt", readKittiTimes(seq + "/times.txt"));
	ASSERT_EQ(devkit.size(), 10u);
	writeKittiPoses(dir + "/00.txt", vehicleToCamera(cameraToVehicle(devkit, Tr), Tr));
	EXPECT_LT(largestDifference(readKittiPoses(dir + "/00.txt"), devkit), 1e-8);
	EXPECT_GT(pathLength(devkit), 5.0);
}

TEST(KittiPoses, TheFormatOfAFileThatIsNeitherIsAnError)
{
	const std::string dir = freshDir();
	std::ofstream(dir + "/seven.txt") << "# a comment\n\n1 2 3 4 5 6 7\n";
	std::ofstream(dir + "/empty.txt") << "# only a comment\n";
	expectInputError([&] { trajectoryFormatOf(dir + "/seven.txt"); }, {dir + "/seven.txt", "line 3", "7 values"});
	expectInputError([&] { trajectoryFormatOf(dir + "/empty.txt"); }, {"no pose"});
	expectInputError([&] { trajectoryFormatOf(dir); }, {dir, "is a directory"});
	expectInputError([&] { readTum(dir); }, {dir, "is a directory"});
}

TEST(Camera0Note, KittiImportCarriesCameraZeroWhicheverCameraItTakes)
{
	const std::string root = sharedData("kitti_odometry_snippets"), dir = freshDir();
	KittiOdometryImport opt;
	opt.root = root;
	opt.seq = "00";
	opt.camera = 2;
	opt.out = dir + "/00.rawlog";
	importKittiOdometry(opt);
	const Eigen::Isometry3d Tr = readKittiOdometryCalib(root + "/sequences/00/calib.txt").cam0_T_velo;

	RawlogReader reader(opt.out);
	Frame f;
	std::size_t frames = 0;
	while (reader.next(f)) ++frames;
	EXPECT_EQ(frames, 10u);
	ASSERT_TRUE(reader.vehicleTCamera0().has_value());
	EXPECT_LT((reader.vehicleTCamera0()->inverse().matrix() - Tr.matrix()).cwiseAbs().maxCoeff(), 1e-12);
	// Camera 2 is camera 0 moved 6 cm to the left: the images' own camera is not camera 0.
	const Eigen::Vector3d cam2_in_cam0 = Tr * f.rig.vehicle_T_camera.translation();
	EXPECT_NEAR(cam2_in_cam0.x(), -0.06, 0.01);  // x is to the right
	EXPECT_EQ(reader.stats().other_labels, 0u);  // the note is no sensor's
}

TEST(Camera0Note, ARawlogWithoutOneHasNoCameraZeroAndABadOneIsAnError)
{
	const std::string dir = freshDir();
	Frame f;
	f.has_scan = true;
	f.scan.push_back({1, 2, 3});
	f.rig.has_lidar = true;
	{
		RawlogWriter w(dir + "/plain.rawlog");
		w.writeFrame(f);
		w.commit();
	}
	RawlogReaderOptions ropt;
	ropt.need_camera = false;
	RawlogReader plain(dir + "/plain.rawlog", ropt);
	Frame g;
	while (plain.next(g))
	{
	}
	EXPECT_FALSE(plain.vehicleTCamera0().has_value());

	{
		RawlogWriter w(dir + "/bad.rawlog");
		auto note = toCamera0Note(Eigen::Isometry3d::Identity(), 0);
		note->text = "vehicle_T_camera0 (row-major 3x4): 1 2 3";
		w.write(*note);
		w.writeFrame(f);
		w.commit();
	}
	RawlogReader bad(dir + "/bad.rawlog", ropt);
	expectInputError([&] { bad.next(g); }, {dir + "/bad.rawlog", "the note of KITTI's camera 0", "expected 12 numbers"});
}
