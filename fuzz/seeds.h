#pragma once
// The seed corpus of each fuzz target: real files from ../shared/data (KITTI, MRPT's samples) and the
// project's own INI files, small enough that a mutation often lands in a header or a count.
#include <vlo/core/frame.h>

#include <string>
#include <vector>

namespace vlo::fuzz
{
/// Contents of the seed files of `target`. Archives are unpacked once under `work`
/// (e.g. <build>/test_data, shared with the unit tests); throws std::runtime_error if that fails.
std::vector<std::string> seedsOf(const std::string& target, const std::string& work);
/// 3 frames of KITTI odometry 00: a 48x32 crop of each colour image and every 200th point of each
/// scan, with the real calibration (LiDAR = vehicle frame), 0.1 s apart from t = 0.
std::vector<Frame> kittiSeedFrames(const std::string& work);
/// The seeds of the "rosbag" target: kittiSeedFrames written as ROS 1 bags (library vlo_fuzz_rosbag).
std::vector<std::string> rosbagSeeds(const std::string& work);
}  // namespace vlo::fuzz
