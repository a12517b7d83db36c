#pragma once
// KITTI raw ground truth from the OXTS RT3003 GPS/IMU records (oxts/data/*.txt), as the KITTI
// devkit's convertOxtsToPose makes it: a Mercator projection scaled by the first record's latitude,
// R = Rz(yaw) Ry(pitch) Rx(roll), relative to the first record; then moved into the Velodyne
// (= vehicle) frame with calib_imu_to_velo.txt. Only eval and tests read it: it is ground truth.
#include <vlo/io/trajectory.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace vlo::io
{
/// The first six values of an OXTS record: position and orientation of the IMU.
struct OxtsRecord
{
	double lat = 0, lon = 0;  ///< [deg]
	double alt = 0;  ///< [m]
	double roll = 0, pitch = 0, yaw = 0;  ///< [rad]
};

/// Reads one record file (30 numbers on one line). Throws InputError naming the file.
OxtsRecord readOxtsRecord(const std::string& path);

/// The devkit's poses: each record's IMU frame in that of the first record.
std::vector<Eigen::Isometry3d> oxtsPoses(const std::vector<OxtsRecord>& records);

/// The records as a trajectory of the Velodyne frame relative to its first pose, at the records' times.
Trajectory oxtsVelodyneTrajectory(
	const std::vector<OxtsRecord>& records, const std::vector<double>& times, const Eigen::Isometry3d& velo_T_imu);
}  // namespace vlo::io
