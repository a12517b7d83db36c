#include <vlo/core/error.h>
#include <vlo/core/input_file.h>
#include <vlo/core/stderr_capture.h>
#include <vlo/rosbag/yaml_file.h>

namespace vlo::rosbag_io
{
mrpt::containers::yaml readYamlFile(const std::string& path)
{
	requireInputFile(path);
	StderrCapture capture;
	auto doc = mrpt::containers::yaml::FromFile(path);
	std::string said = capture.taken();
	if (said.empty()) return doc;
	// "<memory-@0x55..-0x55..>:3:1: error: ...": the parser read the file from memory.
	if (said.rfind("<memory", 0) == 0 && said.find(">:") != std::string::npos) said = said.substr(said.find(">:") + 2);
	failInput(path, "not valid YAML (" + said + ")");
}
}  // namespace vlo::rosbag_io
