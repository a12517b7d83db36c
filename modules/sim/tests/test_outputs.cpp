// What vlo-sim writes: the rawlog read back frame by frame, the ground truth file, and the KITTI
// odometry export with KITTI's conventions (Tr maps LiDAR to camera 0, poses are camera-0 poses).
#include <gtest/gtest.h>

#include <cmath>
#include <vlo/core/error.h>
#include <vlo/core/se3.h>
#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>
#include <vlo/sim/kitti_export.h>
#include <vlo/sim/sequence_writer.h>

#include <cstring>
#include <filesystem>
#include <fstream>

using namespace vlo;
using namespace vlo::sim;
namespace fs = std::filesystem;

namespace
{
fs::path freshDir(const std::string& name)
{
	const fs::path d = fs::path(testing::TempDir()) / ("vlo_sim_" + name + "_" + std::to_string(::getpid()));
	fs::remove_all(d);
	fs::create_directories(d);
	return d;
}

SimConfig shortDrive()
{
	SimConfig c;
	c.scenario = Scenario::Trees;  // few textures: two worlds fit in one test process
	c.lidar = vlp16();
	c.frames = 3;
	c.seed = 21;
	return c;
}

bool sameImage(const mrpt::img::CImage& a, const mrpt::img::CImage& b)
{
	if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight() || a.isColor() || b.isColor()) return false;
	for (unsigned r = 0; r < a.getHeight(); ++r)
		if (std::memcmp(a.ptrLine<uint8_t>(r), b.ptrLine<uint8_t>(r), a.getWidth()) != 0) return false;
	return true;
}

bool sameScan(const PointCloud& a, const PointCloud& b)
{
	if (a.size() != b.size()) return false;
	for (std::size_t i = 0; i < a.size(); ++i)
		if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].z != b[i].z || std::fabs(a[i].intensity - b[i].intensity) > 1e-3f)
			return false;
	return true;
}
}  // namespace

TEST(Outputs, RawlogGroundTruthAndKittiExportHoldTheRenderedFrames)
{
	const fs::path dir = freshDir("outputs");
	OutputOptions out;
	out.rawlog = (dir / "drive.rawlog").string();
	out.kitti_dir = (dir / "kitti").string();
	out.progress = false;
	std::vector<Frame> frames;
	Trajectory truth;
	SensorRig rig;
	{
		Simulator sim(shortDrive());
		const RunStats st = writeSequence(sim, out);
		EXPECT_EQ(st.frames, 3);
		EXPECT_EQ(st.ground_truth, (dir / "drive.gt.tum").string());
		truth = sim.groundTruth();
		rig = sim.config().rig;
	}
	{
		Simulator again(shortDrive());  // same seed: the same frames, rendered anew
		for (int k = 0; k < 3; ++k) frames.push_back(again.frame(k));
	}

	// Rawlog: frames, times, rig, pixels and points.
	io::RawlogReader reader(out.rawlog);
	Frame f;
	int k = 0;
	for (; reader.next(f); ++k)
	{
		ASSERT_LT(k, 3);
		EXPECT_NEAR(f.t, 0.1 * k, 1e-6);
		EXPECT_TRUE(sameImage(f.image, frames[k].image)) << "frame " << k;
		EXPECT_TRUE(sameScan(f.scan, frames[k].scan)) << "frame " << k;
		EXPECT_TRUE(f.rig.vehicle_T_lidar.isApprox(rig.vehicle_T_lidar, 1e-9));
		EXPECT_TRUE(f.rig.vehicle_T_camera.isApprox(rig.vehicle_T_camera, 1e-9));
		EXPECT_NEAR(f.rig.camera.fx, 718.856, 1e-9);
		EXPECT_NEAR(f.rig.camera.cy, 185.2157, 1e-9);
	}
	EXPECT_EQ(k, 3);

	// Ground truth: vehicle frame, relative to frame 0, the frame times.
	const Trajectory gt = io::readTum(out.rawlog.substr(0, out.rawlog.size() - 7) + ".gt.tum");
	ASSERT_EQ(gt.size(), 3u);
	EXPECT_TRUE(gt[0].pose.isApprox(Eigen::Isometry3d::Identity(), 1e-9));
	for (int i = 0; i < 3; ++i)
	{
		EXPECT_NEAR(gt[i].t, truth[i].t, 1e-9);
		EXPECT_TRUE(gt[i].pose.isApprox(truth[i].pose, 1e-6));
	}
	EXPECT_GT(gt[2].pose.translation().x(), 1.0);  // moving forward at >= 5 m/s

	// KITTI export.
	const std::string seq = out.kitti_dir + "/sequences/00";
	const io::KittiOdometryCalib calib = io::readKittiOdometryCalib(seq + "/calib.txt");
	ASSERT_TRUE(calib.has_tr);
	EXPECT_TRUE(calib.cam0_T_velo.isApprox(rig.vehicle_T_camera.inverse() * rig.vehicle_T_lidar, 1e-9));
	const PinholeCamera K = io::intrinsicsOf(calib.P0, 1241, 376);
	EXPECT_NEAR(K.fx, 718.856, 1e-9);
	EXPECT_NEAR(K.cx, 607.1928, 1e-9);
	const std::vector<double> times = io::readKittiTimes(seq + "/times.txt");
	ASSERT_EQ(times.size(), 3u);
	EXPECT_NEAR(times[2], 0.2, 1e-9);
	// poses/00.txt: camera 0 relative to camera 0 at frame 0 <=> the vehicle ground truth.
	const Trajectory cam = io::readKittiPoses(out.kitti_dir + "/poses/00.txt", times);
	const Trajectory veh = io::cameraToVehicle(cam, rig.vehicle_T_camera.inverse());
	for (int i = 0; i < 3; ++i) EXPECT_TRUE(veh[i].pose.isApprox(gt[i].pose, 1e-6)) << i;
	// Velodyne frame = LiDAR frame: the same floats as the rawlog.
	for (int i = 0; i < 3; ++i)
	{
		char name[16];
		std::snprintf(name, sizeof(name), "%06d", i);
		PointCloud bin;
		io::readKittiBin(seq + "/velodyne/" + name + ".bin", bin);
		for (LidarPoint& p : bin) p.intensity *= 255.0f;  // KITTI's reflectance in [0, 1], the scan's 8-bit
		EXPECT_TRUE(sameScan(bin, frames[i].scan)) << i;
		mrpt::img::CImage png;
		ASSERT_TRUE(png.loadFromFile(seq + "/image_0/" + name + ".png", 0));
		EXPECT_TRUE(sameImage(png, frames[i].image)) << i;
	}
	EXPECT_FALSE(fs::exists(out.kitti_dir + ".partial"));
	EXPECT_FALSE(fs::exists(out.rawlog + ".partial"));
	fs::remove_all(dir);
}

TEST(Outputs, RefusesToReplaceAFolderItDidNotWrite)
{
	const fs::path dir = freshDir("refuse");
	fs::create_directories(dir / "kitti");
	std::ofstream(dir / "kitti" / "precious.txt") << "keep me\n";
	EXPECT_THROW(KittiExporter((dir / "kitti").string(), defaultRig(), "test"), InputError);
	EXPECT_TRUE(fs::exists(dir / "kitti" / "precious.txt"));
	EXPECT_FALSE(fs::exists(dir / "kitti.partial"));
	fs::remove_all(dir);
}
