#pragma once
// sensor_msgs/CameraInfo -> PinholeCamera (intrinsics and lens distortion of the image as stored).
#include <vlo/core/frame.h>

#include <sensor_msgs/CameraInfo.h>

#include <string>

namespace vlo::rosbag_io
{
/// The image is rectified when its topic names a rectified stream ("image_rect...") or D is all zeros:
/// then the intrinsics are P's (fx fy cx cy; P's Tx, a stereo baseline, is ignored) and there is no
/// distortion. Otherwise K with D: plumb_bob (5: k1 k2 p1 p2 k3), rational_polynomial (8: k1 k2 p1 p2
/// k3 k4 k5 k6), equidistant (4: k1 k2 k3 k4 -> kannala_brandt). An unknown model, a D of the wrong
/// length, binning or an ROI, or a K without focal lengths: InputError(where, ...).
PinholeCamera fromCameraInfo(const sensor_msgs::CameraInfo& msg, const std::string& image_topic, const std::string& where);

/// A camera calibration file as ROS's camera_calibration / camera_info_manager write it (image_width,
/// image_height, camera_matrix, distortion_model, distortion_coefficients, projection_matrix; each matrix
/// as {rows, cols, data}), for bags without a CameraInfo topic. Throws InputError naming the file.
sensor_msgs::CameraInfo readCameraInfoFile(const std::string& path);

/// True for the names of rectified image streams (".../image_rect", ".../image_rect_color/compressed").
bool isRectifiedTopic(const std::string& image_topic);
}  // namespace vlo::rosbag_io
