// Bags written from a simulated drive are imported and compared, in closed form, with the frames they
// were written from: points, rings, times, intrinsics, distortion, extrinsics, stamps, ground truth.
#include "rosbag_test_util.h"

#include <vlo/io/kitti_import.h>
#include <vlo/io/trajectory.h>

#include <fstream>
#include <iomanip>

namespace vlo::test
{
namespace
{
struct Case
{
	std::string name, encoding;
	mrpt::img::DistortionModel model;
	std::array<double, 8> dist;
	bool tf_static, tf_dynamic, big_endian;
};

/// lidar_T_camera as --extrinsics FILE.yaml holds it.
void writeExtrinsicsFile(const std::string& path, const Eigen::Isometry3d& l_T_c)
{
	std::ofstream f(path);
	f.precision(17);
	f << "lidar_T_camera: [";
	for (int i = 0; i < 16; ++i) f << (i ? ", " : "") << l_T_c.matrix()(i / 4, i % 4);
	f << "]\n";
}

/// The frames as a driver would record them, with the case's camera model.
std::vector<Frame> sourceFrames(const Case& c)
{
	auto frames = simFrames();
	for (auto& f : frames)
	{
		f.rig.camera.distortion = c.model;
		f.rig.camera.dist = c.dist;
	}
	return frames;
}

void expectSameFrames(const std::vector<Frame>& src, const std::vector<Frame>& got, bool lossless_images)
{
	ASSERT_EQ(got.size(), src.size());
	for (std::size_t k = 0; k < src.size(); ++k)
	{
		const Frame &s = src[k], &g = got[k];
		EXPECT_NEAR(g.t, s.t, 1e-7) << k;
		// Extrinsics: the vehicle frame is the LiDAR frame; the camera keeps its pose relative to the LiDAR.
		EXPECT_TRUE(g.rig.vehicle_T_lidar.isApprox(Eigen::Isometry3d::Identity(), 1e-12));
		const Eigen::Isometry3d l_T_c = s.rig.vehicle_T_lidar.inverse() * s.rig.vehicle_T_camera;
		EXPECT_LT((g.rig.vehicle_T_camera.matrix() - l_T_c.matrix()).cwiseAbs().maxCoeff(), 1e-9) << k;
		// Intrinsics and distortion as given.
		const auto &sc = s.rig.camera, &gc = g.rig.camera;
		EXPECT_EQ(gc.fx, sc.fx);
		EXPECT_EQ(gc.fy, sc.fy);
		EXPECT_EQ(gc.cx, sc.cx);
		EXPECT_EQ(gc.cy, sc.cy);
		EXPECT_EQ(gc.width, sc.width);
		EXPECT_EQ(gc.height, sc.height);
		EXPECT_EQ(gc.distortion, sc.distortion);
		for (int i = 0; i < 8; ++i) EXPECT_EQ(gc.dist[i], sc.dist[i]) << i;
		// Points: same count, coordinates, bottom-up rings, times (to 1 us: the rawlog stores them through
		// mrpt::system::timestampAdd, which truncates to whole microseconds), 8-bit intensity.
		ASSERT_EQ(g.scan.size(), s.scan.size()) << k;
		EXPECT_TRUE(g.scan.has_ring && g.scan.has_time);
		for (std::size_t i = 0; i < s.scan.size(); ++i)
		{
			const auto &p = s.scan[i], &q = g.scan[i];
			ASSERT_EQ(q.x, p.x);
			ASSERT_EQ(q.y, p.y);
			ASSERT_EQ(q.z, p.z);
			ASSERT_EQ(q.ring, 15 - p.ring) << "top-down id " << p.ring;
			ASSERT_NEAR(q.time, p.time, 1e-6 + 1e-8);
			ASSERT_EQ(q.intensity, float(std::clamp(std::lround(p.intensity), 0L, 255L)));
		}
		// Pixels: exact unless JPEG.
		const cv::Mat a = s.image.asCvMatRef(), b = g.image.asCvMatRef();
		ASSERT_EQ(a.size(), b.size());
		const double diff = cv::norm(a, b, cv::NORM_L1) / double(a.total());
		if (lossless_images) EXPECT_EQ(diff, 0) << k;
		else EXPECT_LT(diff, 2.0) << k;
	}
}

class RosbagRoundTrip : public ::testing::TestWithParam<Case>
{
};

TEST_P(RosbagRoundTrip, ImportedRawlogHoldsWhatTheBagHeld)
{
	const Case& c = GetParam();
	const std::string dir = freshDir();
	BagLayout layout;
	layout.image_encoding = c.encoding;
	layout.tf_static = c.tf_static;
	layout.tf_as_dynamic = c.tf_dynamic;
	layout.big_endian = c.big_endian;
	layout.scan_delay = 0.25;  // scan k arrives after images k+1 and k+2: arrival order != stamp order
	if (c.encoding == "png" || c.encoding == "jpeg") layout.image_topic = "/camera/image_raw/compressed";
	const auto src = sourceFrames(c);
	writeBag(dir + "/in.bag", src, {}, layout);

	auto opt = importOptions(dir + "/in.bag", dir + "/out.rawlog", layout);
	const Eigen::Isometry3d l_T_c = src[0].rig.vehicle_T_lidar.inverse() * src[0].rig.vehicle_T_camera;
	if (!c.tf_static)  // the same extrinsics from a file, row-major
	{
		opt.extrinsics = dir + "/extrinsics.yaml";
		writeExtrinsicsFile(opt.extrinsics, l_T_c);
	}
	const auto summary = rosbag_io::importRosbag(opt);
	EXPECT_EQ(summary.images, src.size());
	EXPECT_EQ(summary.scans, src.size());
	EXPECT_EQ(summary.late_messages, 0u);
	EXPECT_EQ(summary.extrinsics_source, c.tf_static ? (c.tf_dynamic ? "/tf_static and static /tf" : "/tf_static") : opt.extrinsics);
	expectSameFrames(src, readFrames(opt.out), c.encoding != "jpeg");
}

using mrpt::img::DistortionModel;
INSTANTIATE_TEST_SUITE_P(Layouts, RosbagRoundTrip,
	::testing::Values(Case{"mono8_plumb_bob", "mono8", DistortionModel::plumb_bob, {-0.3, 0.1, 1e-3, -2e-3, 0.02, 0, 0, 0}, true, false, false},
		Case{"rgb8_rational", "rgb8", DistortionModel::plumb_bob, {-0.3, 0.1, 1e-3, -2e-3, 0.02, 0.01, -0.02, 0.03}, true, true, false},
		Case{"bgra8_equidistant_bigendian", "bgra8", DistortionModel::kannala_brandt, {0.1, -0.02, 0, 0, 3e-3, -1e-3, 0, 0}, false, false, true},
		Case{"mono16_ideal", "mono16", DistortionModel::none, {}, true, false, false},
		Case{"png_plumb_bob", "png", DistortionModel::plumb_bob, {-0.2, 0.05, 0, 0, 0, 0, 0, 0}, true, false, true},
		Case{"jpeg_no_tf", "jpeg", DistortionModel::none, {}, false, false, false}),
	[](const auto& info) { return info.param.name; });

TEST(RosbagImport, GroundTruthInTheVehicleFrameRelativeToTheFirstPose)
{
	const std::string dir = freshDir();
	Trajectory gt;
	const auto& frames = simFrames(&gt);
	// The bag's ground truth: the vehicle (base_link) in a world frame that is not the first pose.
	Eigen::Isometry3d world_T_start = Eigen::Isometry3d::Identity();
	world_T_start.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	world_T_start.translation() = Eigen::Vector3d(100, -20, 3);
	Trajectory world = gt;
	for (auto& p : world) p.pose = world_T_start * p.pose;
	for (const std::string type : {"nav_msgs/Odometry", "geometry_msgs/PointStamped"})
	{
		BagLayout layout;
		layout.gt_type = type;
		writeBag(dir + "/gt.bag", frames, world, layout);
		auto opt = importOptions(dir + "/gt.bag", dir + "/out.rawlog", layout);
		opt.gt_topic = layout.gt_topic;
		opt.vehicle_frame = "base_link";
		const auto summary = rosbag_io::importRosbag(opt);
		ASSERT_EQ(summary.ground_truth, io::groundTruthPathFor(opt.out));
		const Trajectory got = io::readTum(summary.ground_truth);
		ASSERT_EQ(got.size(), gt.size());
		for (std::size_t k = 0; k < gt.size(); ++k)
		{
			EXPECT_NEAR(got[k].t, gt[k].t, 1e-9);
			if (type == "nav_msgs/Odometry")  // the simulator's own ground truth (relative to frame 0)
				EXPECT_LT((got[k].pose.matrix() - gt[k].pose.matrix()).cwiseAbs().maxCoeff(), 1e-8) << k;
			else  // positions only: displacement since the first, identity rotation
			{
				const Eigen::Vector3d d = world[k].pose.translation() - world[0].pose.translation();
				EXPECT_LT((got[k].pose.translation() - d).norm(), 1e-8) << k;
				EXPECT_TRUE(got[k].pose.linear().isIdentity(1e-12));
			}
		}
		// With --vehicle-frame the sensors keep their placement on the vehicle.
		const auto imported = readFrames(opt.out);
		EXPECT_TRUE(imported[0].rig.vehicle_T_lidar.isApprox(frames[0].rig.vehicle_T_lidar, 1e-12));
		EXPECT_TRUE(imported[0].rig.vehicle_T_camera.isApprox(frames[0].rig.vehicle_T_camera, 1e-12));
	}
}

TEST(RosbagImport, SeveralBagsAreOneRecording)
{
	const std::string dir = freshDir();
	const auto& frames = simFrames();
	const std::size_t half = frames.size() / 2;
	writeBag(dir + "/a.bag", {frames.begin(), frames.begin() + half}, {}, {});
	BagLayout second;
	second.tf_static = false;  // /tf_static is recorded once, in the first bag
	writeBag(dir + "/b.bag", {frames.begin() + half, frames.end()}, {}, second);
	auto opt = importOptions(dir + "/b.bag", dir + "/out.rawlog");
	opt.bags = {dir + "/b.bag", dir + "/a.bag"};  // any order: messages go by stamp
	const auto s = rosbag_io::importRosbag(opt);
	EXPECT_EQ(s.images, frames.size());
	EXPECT_EQ(s.scans, frames.size());
	expectSameFrames(frames, readFrames(opt.out), true);
}
TEST(RosbagImport, S3eLayoutWithCalibrationFiles)
{
	// S3E's bags: /Alpha/left_camera/compressed (JPEG), /Alpha/velodyne_points, no CameraInfo, no tf; the
	// calibration comes in files (here: the simulated camera with S3E's Alpha plumb_bob coefficients).
	const std::string dir = freshDir();
	auto frames = simFrames();
	for (auto& f : frames)
	{
		f.rig.camera.distortion = mrpt::img::DistortionModel::plumb_bob;
		f.rig.camera.dist = {-0.052628389768906, 0.100832689624109, 0.000395112517197, 0.000362060505238, 0, 0, 0, 0};
	}
	BagLayout layout;
	layout.image_encoding = "png";
	layout.image_topic = "/Alpha/left_camera/compressed";
	layout.lidar_topic = "/Alpha/velodyne_points";
	layout.info_topic = "/unused/camera_info";
	layout.tf_static = false;
	writeBag(dir + "/s3e.bag", frames, {}, layout);
	auto opt = importOptions(dir + "/s3e.bag", dir + "/out.rawlog", layout);
	opt.extrinsics = dir + "/alpha_extrinsics.yaml";
	writeExtrinsicsFile(opt.extrinsics, frames[0].rig.vehicle_T_lidar.inverse() * frames[0].rig.vehicle_T_camera);
	opt.camera_info_file = dir + "/alpha_left.yaml";
	const auto& c = frames[0].rig.camera;
	std::ofstream(opt.camera_info_file) << std::setprecision(17) << "image_width: " << c.width << "\nimage_height: " << c.height
										<< "\ncamera_name: alpha_left\ncamera_matrix: {rows: 3, cols: 3, data: [" << c.fx << ", 0, "
										<< c.cx << ", 0, " << c.fy << ", " << c.cy << ", 0, 0, 1]}\ndistortion_model: plumb_bob\n"
										<< "distortion_coefficients: {rows: 1, cols: 5, data: [" << c.dist[0] << ", " << c.dist[1]
										<< ", " << c.dist[2] << ", " << c.dist[3] << ", 0.0]}\n";
	rosbag_io::importRosbag(opt);
	expectSameFrames(frames, readFrames(opt.out), true);
}
}  // namespace
}  // namespace vlo::test
