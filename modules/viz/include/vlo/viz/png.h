#pragma once
// PNG output that appears complete or not at all (encoded in memory, written to "<path>.partial",
// renamed into place).
#include <opencv2/core/mat.hpp>

#include <string>

namespace vlo::viz
{
/// Writes an 8-bit BGR or grayscale image. Throws InputError naming the path on failure.
void writePng(const std::string& path, const cv::Mat& image);
}  // namespace vlo::viz
