#pragma once
// The readers under fuzzing, each behind one signature: read the file at `path` completely.
// A reader passes on an input when it reads it or throws vlo::InputError with one printable line
// that names the file; anything else (another exception type, a crash, a hang) is a bug.
#include <string>
#include <vector>

namespace vlo::fuzz
{
struct Target
{
	std::string name;  ///< e.g. "rawlog", "kitti_calib"
	std::string file_name;  ///< what the input is called on disk (readers look at extensions)
	void (*read)(const std::string& path);
};

/// The readers of modules/io (library vlo_fuzz_io).
std::vector<Target> ioTargets();
/// vlo-run's INI loading (library vlo_fuzz_ini, which needs the whole pipeline).
Target iniTarget();
/// vlo-import rosbag (library vlo_fuzz_rosbag, which needs ROS's bag library).
Target rosbagTarget();

/// Every frame of a camera + LiDAR rawlog / every pose of a TUM file, read; throws std::logic_error when a
/// value read is not usable (what the "rawlog" and "tum" targets check).
void readRawlogChecked(const std::string& path);
void readTumChecked(const std::string& path);
/// The one called `name` in `among`; throws std::invalid_argument if there is none.
const Target& findTarget(const std::vector<Target>& among, const std::string& name);

/// Writes `bytes` to `<dir>/<file_name>` and runs the target on it. Returns "" when it read or threw
/// a proper InputError, else what went wrong (exception type and message, or the bad message).
std::string runOne(const Target& t, const std::string& dir, const std::string& bytes);
}  // namespace vlo::fuzz
