#pragma once
// Trajectory files. TUM: "t x y z qx qy qz qw" per line (t in the dataset's own seconds).
// KITTI: 12 numbers per line, the row-major 3x4 pose of camera 0 relative to camera 0 at frame 0.
#include <vlo/core/trajectory.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace vlo::io
{
/// Reads a TUM file. '#' comments and blank lines are skipped. Throws InputError naming the file and
/// line for a malformed or non-finite line, and for timestamps that do not increase.
Trajectory readTum(const std::string& path);
/// Writes atomically (never a half-written file).
void writeTum(const std::string& path, const Trajectory& traj);

enum class TrajectoryFormat
{
	Tum,  ///< 8 numbers a line
	Kitti  ///< 12 numbers a line
};
/// The format of a trajectory file, by the count of numbers on its first line that is neither blank nor a
/// comment. Throws InputError naming the file when it cannot be read, holds no such line, or has another count.
TrajectoryFormat trajectoryFormatOf(const std::string& path);

/// Reads KITTI 3x4 poses (one per line); times come from `times` (same count) or are 0.1 s apart.
Trajectory readKittiPoses(const std::string& path, const std::vector<double>& times = {});
void writeKittiPoses(const std::string& path, const Trajectory& traj);
/// Reads KITTI times.txt (one number of seconds per line).
std::vector<double> readKittiTimes(const std::string& path);

/// KITTI camera-0 poses <-> vehicle (Velodyne) poses, given cam0_T_velo (KITTI's Tr):
/// V_k = Tr^-1 * C_k * Tr, so both start at identity when C_0 is identity.
Trajectory cameraToVehicle(const Trajectory& cam0, const Eigen::Isometry3d& cam0_T_velo);
Trajectory vehicleToCamera(const Trajectory& vehicle, const Eigen::Isometry3d& cam0_T_velo);
}  // namespace vlo::io
