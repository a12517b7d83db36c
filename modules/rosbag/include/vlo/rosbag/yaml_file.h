#pragma once
// A YAML file the user gives (camera calibration, extrinsics), read with MRPT's reader, whose parser prints
// its syntax errors to stderr and returns what it got so far.
#include <mrpt/containers/yaml.h>

#include <string>

namespace vlo::rosbag_io
{
/// Throws InputError naming the file for a directory, a missing file, or YAML that does not parse
/// ("not valid YAML (3:1: did not find expected node content)"), in one line.
mrpt::containers::yaml readYamlFile(const std::string& path);
}  // namespace vlo::rosbag_io
