// Broken input: one-line InputError naming the file (bag, or the option), and no output left behind.
#include "rosbag_test_util.h"

#include <fstream>

namespace vlo::test
{
namespace
{
/// Imports and expects the error, then that neither the rawlog nor its partial files exist.
void expectRefused(const RosbagImport& opt, const std::vector<std::string>& parts)
{
	expectInputError([&] { importRosbag(opt); }, parts);
	const fs::path dir = fs::path(opt.out).parent_path();
	for (const auto& e : fs::directory_iterator(dir))
		EXPECT_TRUE(e.path().extension() == ".bag" || e.path().extension() == ".yaml") << "left behind: " << e.path();
}

std::vector<Frame> fewFrames() { return {simFrames().begin(), simFrames().begin() + 3}; }

TEST(RosbagErrors, TruncatedBag)
{
	const std::string dir = freshDir();
	writeBag(dir + "/full.bag", fewFrames(), {}, {});
	const auto size = fs::file_size(dir + "/full.bag");
	fs::copy_file(dir + "/full.bag", dir + "/cut.bag");
	fs::resize_file(dir + "/cut.bag", size * 2 / 3);
	fs::remove(dir + "/full.bag");
	expectRefused(importOptions(dir + "/cut.bag", dir + "/out.rawlog"), {dir + "/cut.bag", "truncated"});
}

TEST(RosbagErrors, MissingTopicListsTheTopicsThere)
{
	const std::string dir = freshDir();
	writeBag(dir + "/in.bag", fewFrames(), {}, {});
	auto opt = importOptions(dir + "/in.bag", dir + "/out.rawlog");
	opt.lidar_topic = "/points_raw";
	expectRefused(opt, {dir + "/in.bag", "--lidar-topic", "no topic '/points_raw'", "/velodyne_points", "/camera/image_raw"});
}

TEST(RosbagErrors, PointCloud2WithoutX)
{
	const std::string dir = freshDir();
	BagLayout l;
	l.drop_x = true;
	writeBag(dir + "/in.bag", fewFrames(), {}, l);
	expectRefused(importOptions(dir + "/in.bag", dir + "/out.rawlog"), {dir + "/in.bag", "/velodyne_points", "without field 'x'"});
}

TEST(RosbagErrors, UnsupportedImageEncoding)
{
	const std::string dir = freshDir();
	BagLayout l;
	l.image_encoding = "bayer_rggb8";
	writeBag(dir + "/in.bag", fewFrames(), {}, l);
	expectRefused(importOptions(dir + "/in.bag", dir + "/out.rawlog"), {dir + "/in.bag", "/camera/image_raw", "'bayer_rggb8' is not supported"});
}

TEST(RosbagErrors, UnknownDistortionModel)
{
	const std::string dir = freshDir();
	auto frames = fewFrames();
	for (auto& f : frames) f.rig.camera.distortion = mrpt::img::DistortionModel::plumb_bob, f.rig.camera.dist[0] = -0.1;
	BagLayout l;
	l.distortion_model = "fov";
	writeBag(dir + "/in.bag", frames, {}, l);
	expectRefused(importOptions(dir + "/in.bag", dir + "/out.rawlog"), {dir + "/in.bag", "/camera/camera_info", "unknown distortion_model 'fov'"});
}

TEST(RosbagErrors, NoExtrinsicsNamesBothWays)
{
	const std::string dir = freshDir();
	BagLayout l;
	l.tf_static = false;
	writeBag(dir + "/in.bag", fewFrames(), {}, l);
	expectRefused(importOptions(dir + "/in.bag", dir + "/out.rawlog"), {dir + "/in.bag", "'velodyne'", "'camera_optical'", "/tf_static", "--extrinsics"});
}

TEST(RosbagErrors, BadExtrinsicsFileAndCameraInfoTopic)
{
	const std::string dir = freshDir();
	BagLayout l;
	l.tf_static = false;
	l.info_topic = "/calib/info";  // not next to the image topic
	writeBag(dir + "/in.bag", fewFrames(), {}, l);
	auto opt = importOptions(dir + "/in.bag", dir + "/out.rawlog");
	expectRefused(opt, {"--camera-info-topic", "/camera/image_raw", dir + "/in.bag"});
	opt.camera_info_topic = l.info_topic;
	opt.extrinsics = dir + "/e.yaml";
	std::ofstream(opt.extrinsics) << "lidar_T_camera: [1, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0]\n";
	expectRefused(opt, {opt.extrinsics, "16 numbers"});
	std::ofstream(opt.extrinsics) << "lidar_T_camera: [2, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1]\n";
	expectRefused(opt, {opt.extrinsics, "not orthonormal"});
}

TEST(RosbagErrors, NotABag)
{
	const std::string dir = freshDir();
	std::ofstream(dir + "/x.bag") << "#ROSBAG V1.2\nnonsense";
	expectRefused(importOptions(dir + "/x.bag", dir + "/out.rawlog"), {dir + "/x.bag"});
	expectRefused(importOptions(dir + "/none.bag", dir + "/out.rawlog"), {dir + "/none.bag", "no such file"});
}
}  // namespace
}  // namespace vlo::test
