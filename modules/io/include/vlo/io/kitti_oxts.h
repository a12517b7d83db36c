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
/// The values of an OXTS record that vlo reads: position, orientation and velocity of the IMU.
struct OxtsRecord
{
	double lat = 0, lon = 0;  ///< [deg]
	double alt = 0;  ///< [m]
	double roll = 0, pitch = 0, yaw = 0;  ///< [rad]
	double vn = 0, ve = 0, vu = 0;  ///< [m/s] north, east, up (fields 7, 8, 11)
	bool has_velocity = false;  ///< the record has those fields (a full record has 30 values)
};

/// Reads one record file (30 numbers on one line). Throws InputError naming the file.
OxtsRecord readOxtsRecord(const std::string& path);

/// The devkit's poses: each record's IMU frame in that of the first record.
std::vector<Eigen::Isometry3d> oxtsPoses(const std::vector<OxtsRecord>& records);

/// The same orientations, but the positions integrated (trapezoid) from the records' velocities at
/// `times` from the first record on: where the GPS positions (0.15-0.2 m in differential mode) wander,
/// the velocities (0.03 m/s) still measure the path's length and each step. Empty when a record has
/// no velocity or the times are not increasing.
std::vector<Eigen::Isometry3d> oxtsDeadReckonedPoses(const std::vector<OxtsRecord>& records, const std::vector<double>& times);

/// IMU poses (of oxtsPoses or oxtsDeadReckonedPoses) as a trajectory of the Velodyne frame relative
/// to its first pose, at the records' times.
Trajectory velodyneTrajectory(
	const std::vector<Eigen::Isometry3d>& imu_poses, const std::vector<double>& times, const Eigen::Isometry3d& velo_T_imu);
}  // namespace vlo::io
