// Broken input: one-line InputError naming the file (bag, or the option), and no output left behind.
#include "rosbag_test_util.h"

#include <vlo/core/interrupt.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace vlo::test
{
namespace
{
/// Imports and expects the error, then that neither the rawlog nor its partial files exist.
void expectRefused(const rosbag_io::RosbagImport& opt, const std::vector<std::string>& parts)
{
	expectInputError([&] { rosbag_io::importRosbag(opt); }, parts);
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

// Issue 34, defect 11: a bag whose recording was not closed has no index; say how to rebuild it.
TEST(RosbagErrors, UnindexedBagGetsTheReindexHint)
{
	const std::string dir = freshDir();
	writeBag(dir + "/in.bag", fewFrames(), {}, {});
	std::ifstream in(dir + "/in.bag", std::ios::binary);
	std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	const std::size_t at = bytes.find("index_pos=");
	ASSERT_NE(at, std::string::npos);
	bytes.replace(at + 10, 8, std::string(8, '\0'));
	std::ofstream(dir + "/open.bag", std::ios::binary) << bytes;
	fs::remove(dir + "/in.bag");
	expectRefused(importOptions(dir + "/open.bag", dir + "/out.rawlog"),
		{dir + "/open.bag", "the bag has no index", "'rosbag reindex " + dir + "/open.bag'"});
	std::ofstream(dir + "/cut.bag", std::ios::binary) << bytes.replace(at + 10, 8, std::string("\x01\0\0\0\0\0\0\0", 8));
	expectRefused(importOptions(dir + "/cut.bag", dir + "/out.rawlog"), {"truncated", "rosbag reindex"});
}

// Issue 34, defect 6: the signal was only looked at every 64 messages, so a short bag's import ignored Ctrl-C.
TEST(RosbagErrors, CtrlCStopsTheImportOfAShortBag)
{
	const std::string dir = freshDir();
	writeBag(dir + "/in.bag", fewFrames(), {}, {});  // 6 messages
	const rosbag_io::RosbagImport opt = importOptions(dir + "/in.bag", dir + "/out.rawlog");
	EXPECT_EXIT(
		{
			installInterruptHandler();
			std::raise(SIGINT);
			try
			{
				rosbag_io::importRosbag(opt);
			}
			catch (const Interrupted&)
			{
				std::exit(fs::exists(opt.out) ? 1 : 130);
			}
			std::exit(0);
		},
		::testing::ExitedWithCode(130), "");
	EXPECT_FALSE(fs::exists(opt.out));
}

/// A copy of in.bag with 4 bytes at `pos` replaced by `value`.
std::string patched(const std::string& dir, std::size_t pos, std::uint32_t value)
{
	std::ifstream in(dir + "/in.bag", std::ios::binary);
	std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	std::memcpy(&bytes[pos], &value, 4);
	const std::string path = dir + "/patched_" + std::to_string(pos) + ".bag";
	std::ofstream(path, std::ios::binary) << bytes;
	return path;
}

// rosbag_storage trusts these sizes: it reallocs what they say (an assertion aborts the process when that
// fails, e.g. under ulimit -v) or reads where they point. Found by fuzz/test_fuzz (target rosbag).
TEST(RosbagErrors, CorruptSizesAreRefusedBeforeRosbagReadsThem)
{
	const std::string dir = freshDir();
	writeBag(dir + "/in.bag", fewFrames(), {}, {});
	std::ifstream in(dir + "/in.bag", std::ios::binary);
	const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	const std::size_t chunkSize = bytes.find(std::string("\x09\0\0\0size=", 9)) + 9;
	ASSERT_NE(chunkSize, std::string::npos + 9);
	const std::string hugeChunk = patched(dir, chunkSize, 0xFFFFFFF0u);
	expectRefused(importOptions(hugeChunk, dir + "/out.rawlog"), {hugeChunk, "a chunk at byte", "size field says 4294967280"});
	const std::string hugeHeader = patched(dir, 13, 0x7FFFFFFFu);  // the bag header record's header length
	expectRefused(importOptions(hugeHeader, dir + "/out.rawlog"), {hugeHeader, "at byte 13", "a header of 2147483647 bytes"});
	const std::string pastEnd = patched(dir, 13, 4096);  // fits the limit, runs past the bag header's padding
	std::ostringstream listing;
	expectInputError([&] { rosbag_io::listRosbagTopics({pastEnd}, listing); }, {pastEnd, "not a readable ROS 1 bag", "past its end"});
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
