#pragma once
// The seed corpus of each fuzz target: real files from ../shared/data (KITTI, MRPT's samples) and the
// project's own INI files, small enough that a mutation often lands in a header or a count.
#include <string>
#include <vector>

namespace vlo::fuzz
{
/// Contents of the seed files of `target`. Archives are unpacked once under `work`
/// (e.g. <build>/test_data, shared with the unit tests); throws std::runtime_error if that fails.
std::vector<std::string> seedsOf(const std::string& target, const std::string& work);
}  // namespace vlo::fuzz
