#pragma once
// Small KITTI data files: Velodyne scans (.bin) and raw-data timestamps.
#include <vlo/core/frame.h>

#include <cstddef>
#include <string>
#include <vector>

namespace vlo::io
{
/// Reads a KITTI Velodyne scan: float32 x, y, z, reflectance per point, Velodyne frame. Points with
/// a non-finite value are dropped; returns how many. Throws InputError naming the file if it is
/// missing or its size is not a multiple of 16 bytes.
std::size_t readKittiBin(const std::string& path, PointCloud& out);
/// Writes the same layout (plain, not gzip). Throws InputError on failure.
void writeKittiBin(const std::string& path, const PointCloud& cloud);

/// Seconds since 1970 (UTC) of a KITTI raw date "2011-09-26 13:02:25.964389445"; false if malformed.
bool parseKittiDate(const std::string& text, double& seconds);
/// Reads a KITTI raw timestamps.txt (one date per line). Throws InputError naming the file and line
/// for a malformed date or a time that does not increase.
std::vector<double> readKittiRawTimestamps(const std::string& path);
}  // namespace vlo::io
