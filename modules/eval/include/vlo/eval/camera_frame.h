#pragma once
// The rig transform that moves vehicle-frame trajectories into camera 0, where the KITTI benchmark
// computes its metric (see vehicleToCamera in vlo/io/trajectory.h).
#include <Eigen/Geometry>
#include <string>

namespace vlo::eval
{
/// 12 numbers, row-major 3x4 [R|t] of cam0_T_vehicle (KITTI's Tr), separated by spaces or commas.
/// Throws InputError naming `where` when the count is wrong or R is not a rotation.
Eigen::Isometry3d parseCam0TVehicle(const std::string& text, const std::string& where = "--cam0-T-vehicle");

/// The "Tr" of a KITTI odometry calib.txt (read with io's KittiCalibFile). Throws InputError naming
/// the file when it cannot be read or has no valid Tr: unlike the importer, no nominal fallback.
Eigen::Isometry3d readKittiCalibTr(const std::string& path);
}  // namespace vlo::eval
