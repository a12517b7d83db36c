#include "seeds.h"
#include "targets.h"

#include <bag_writer.h>
#include <vlo/io/trajectory.h>
#include <vlo/rosbag/rosbag_import.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace vlo::fuzz
{
namespace fs = std::filesystem;

namespace
{
// vlo-import rosbag as a user runs it: --list, then the import of the seeds' topics. What it writes
// must read back with usable values, as the rawlog and TUM targets check them (an InputError there names
// the written file, not the bag: runOne counts it as a failure too).
void importBag(const std::string& path)
{
	std::ostringstream topics;
	rosbag_io::listRosbagTopics({path}, topics);
	const test::BagLayout layout;
	rosbag_io::RosbagImport opt;
	opt.bags = {path};
	opt.lidar_topic = layout.lidar_topic;
	opt.image_topic = layout.image_topic;
	opt.gt_topic = layout.gt_topic;
	opt.vehicle_frame = layout.vehicle_frame;
	opt.out = (fs::path(path).parent_path() / "imported.rawlog").string();
	const rosbag_io::RosbagImportSummary summary = importRosbag(opt);
	readRawlogChecked(summary.rawlog);
	if (!summary.ground_truth.empty()) readTumChecked(summary.ground_truth);
}
}  // namespace

Target rosbagTarget() { return {"rosbag", "input.bag", importBag}; }

std::vector<std::string> rosbagSeeds(const std::string& work)
{
	std::vector<Frame> frames = kittiSeedFrames(work);
	Trajectory gt;  // 1 m and 3 degrees of yaw per frame
	for (const auto& f : frames)
		gt.push_back({f.t, Eigen::Translation3d(10 * f.t, 0, 0) * Eigen::AngleAxisd(0.5 * f.t, Eigen::Vector3d::UnitZ())});
	// Raw RGB with /tf_static, and JPEG with big-endian points and the transforms on /tf: both message
	// kinds of each decoder. Stamps from t = 100 s (ROS time 0 means "no time").
	test::BagLayout raw;
	raw.image_encoding = "rgb8";
	raw.stamp_offset = 100;
	test::BagLayout jpeg = raw;
	jpeg.image_encoding = "jpeg";
	jpeg.big_endian = true;
	jpeg.tf_as_dynamic = true;
	std::vector<std::string> seeds;
	for (const auto& layout : {raw, jpeg})
	{
		const std::string path = work + "/fuzz_seed_" + std::to_string(::getpid()) + ".bag";
		test::writeBag(path, frames, gt, layout);
		std::ifstream in(path, std::ios::binary);
		seeds.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
		fs::remove(path);
	}
	return seeds;
}
}  // namespace vlo::fuzz
