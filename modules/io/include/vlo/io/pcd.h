#pragma once
// Point Cloud Data files (PCD v0.7) through PCL's io library.
// Writes x y z intensity as float32, binary or ascii. Reads ascii, binary and binary_compressed files with any
// fields (x, y, z required; intensity optional, else 0; others skipped).
#include <vlo/core/frame.h>

#include <string>

namespace vlo::io
{
enum class PcdFormat
{
	Binary,
	Ascii
};

/// Atomic: the file appears complete or not at all. Throws InputError naming the file on failure.
void writePcd(const std::string& path, const PointCloud& cloud, PcdFormat format = PcdFormat::Binary);

/// Points with a non-finite x, y or z (PCL's organised clouds hold NaN for no return) are dropped.
/// Throws InputError naming the file (and the header line) for a malformed or truncated file.
PointCloud readPcd(const std::string& path);
}  // namespace vlo::io
