#pragma once
// --extrinsics FILE.yaml: "lidar_T_camera: [16 numbers]", row-major, the pose of the camera's optical
// frame in the LiDAR frame.
#include <Eigen/Geometry>
#include <string>

namespace vlo::rosbag_io
{
/// Throws InputError naming the file when it is missing, lacks the key, has not 16 finite numbers, or
/// the matrix is not a rigid transform (last row 0 0 0 1, rotation orthonormal within 1e-6); the
/// rotation is projected onto SO(3).
Eigen::Isometry3d readExtrinsicsFile(const std::string& path);
}  // namespace vlo::rosbag_io
