#pragma once
// Keyframes: the frames the loop closure keeps, one every few metres or degrees of the odometry, each
// with its scan de-skewed, in the vehicle frame and thinned (what the descriptor and the registration use).
#include <vlo/core/frame.h>
#include <vlo/core/pose_information.h>

#include <Eigen/Geometry>
#include <vector>

namespace vlo::loop
{
using ScanPoints = std::vector<Eigen::Vector3f>;  // float: 4000 keyframes' scans stay in memory

struct Keyframe
{
	long long frame = -1;
	double t = 0;
	Eigen::Isometry3d odometry = Eigen::Isometry3d::Identity();  ///< world_T_vehicle of the odometry
	double path = 0;  ///< [m] the odometry's path from the first frame to this one
	ScanPoints points;  ///< vehicle frame
	/// Of the odometry's motion from the previous keyframe to this one (the pose graph's [translation;
	/// rotation]): the frames' covariances composed (OdometryChain). Zero for the first keyframe.
	Matrix6d odometry_covariance = Matrix6d::Zero();
};

/// Decides which frames become keyframes: the first, then each one that moved keyframe_distance or
/// turned keyframe_angle from the last keyframe.
class KeyframeSelector
{
   public:
	KeyframeSelector(double distance, double angle_rad) : distance_(distance), angle_(angle_rad) {}
	bool take(const Eigen::Isometry3d& world_T_vehicle);

   private:
	double distance_, angle_;
	bool first_ = true;
	Eigen::Isometry3d last_ = Eigen::Isometry3d::Identity();
};

/// The scan thinned to one point per `voxel` (in the LiDAR frame, before the de-skew: the de-skew's
/// exponential per point then runs on a few thousand points, not on the whole sweep), de-skewed with
/// the LiDAR's motion `lidar_motion` over `dt` and moved into the vehicle frame.
ScanPoints keyframeScan(const PointCloud& scan, const Eigen::Isometry3d& lidar_motion, double dt,
	const Eigen::Isometry3d& vehicle_T_lidar, double voxel);
}  // namespace vlo::loop
