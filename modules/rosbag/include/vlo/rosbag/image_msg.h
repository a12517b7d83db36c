#pragma once
// sensor_msgs/Image and CompressedImage -> 8-bit grey CImage (OpenCV; no cv_bridge).
#include <mrpt/img/CImage.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>

#include <string>

namespace vlo::rosbag_io
{
/// mono8 / 8UC1, mono16 / 16UC1 (scaled by 255/65535, rounded), rgb8, bgr8, rgba8, bgra8. Anything else,
/// or a step or size that does not fit the data: InputError(where, ...) naming the encoding.
mrpt::img::CImage decodeImage(const sensor_msgs::Image& msg, const std::string& where);
/// format "jpeg" / "png" (as image_transport writes, e.g. "bgr8; jpeg compressed bgr8"); else InputError.
mrpt::img::CImage decodeCompressedImage(const sensor_msgs::CompressedImage& msg, const std::string& where);
}  // namespace vlo::rosbag_io
