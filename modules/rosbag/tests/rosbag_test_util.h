#pragma once
// Shared helpers of the rosbag tests: a short simulated VLP-16 drive, read back as frames, with
// Velodyne-style per-point ring and time added, and bag import helpers.
#include "bag_writer.h"
#include "io_test_util.h"  // freshDir, expectInputError, readFrames (modules/io/tests)

#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/rosbag/rosbag_import.h>

#include <opencv2/core.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace vlo::test
{
namespace fs = std::filesystem;

/// Frames of an 8-frame noise-free VLP-16 drive (vlo-sim, run once per process), with ring and time.
inline const std::vector<Frame>& simFrames(Trajectory* gt = nullptr)
{
	static std::vector<Frame> frames;
	static Trajectory truth;
	if (frames.empty())
	{
		const fs::path dir = fs::path(VLO_BIN_DIR) / ".." / "test_data" / ("rosbag_sim_" + std::to_string(::getpid()));
		fs::create_directories(dir);
		const std::string rawlog = (dir / "sim.rawlog").string();
		const std::string cmd = std::string(VLO_BIN_DIR) + "/vlo-sim --scenario urban --lidar vlp16 --frames 8 --seed 3 --no-noise --quiet --out " + rawlog;
		if (std::system(cmd.c_str()) != 0) ADD_FAILURE() << "failed: " << cmd;
		io::RawlogReader reader(rawlog);
		for (Frame f; reader.next(f);)
		{
			f.image = mrpt::img::CImage(f.image.asCvMatRef().clone(), mrpt::img::SHALLOW_COPY);  // the files go below
			addVlp16Fields(f.scan);
			frames.push_back(f);
		}
		truth = io::readTum((dir / "sim.gt.tum").string());
		fs::remove_all(dir);
	}
	if (gt) *gt = truth;
	return frames;
}

inline rosbag_io::RosbagImport importOptions(const std::string& bag, const std::string& out, const BagLayout& l = {})
{
	rosbag_io::RosbagImport opt;
	opt.bags = {bag};
	opt.lidar_topic = l.lidar_topic;
	opt.image_topic = l.image_topic;
	opt.out = out;
	return opt;
}

}  // namespace vlo::test
