#pragma once
// A check of a ROS 1 bag's record structure before rosbag_storage reads it. rosbag_storage trusts the
// sizes it finds: a corrupt length makes it realloc up to 4 GB and abort on an assertion when that
// fails, and a corrupt index offset makes it read outside its buffers. Every size and offset it will
// follow is checked here against the file and the records around it.
#include <string>

namespace vlo::rosbag_io
{
/// Throws InputError naming `path` and the first record that is inconsistent. Format 2.0 only (what ROS
/// 1 has written since 2010); compressed chunks are checked up to their stated size (at most 256 MB).
void checkBagStructure(const std::string& path);
}  // namespace vlo::rosbag_io
