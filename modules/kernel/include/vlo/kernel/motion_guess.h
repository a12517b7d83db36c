#pragma once
// What a motion source gives the LiDAR odometry for a frame: the vehicle's motion and how far it can be
// trusted, one value (the odometry weighs the guess by its quality).
#include <vlo/kernel/motion_quality.h>

#include <Eigen/Geometry>

namespace vlo::kernel
{
struct MotionGuess
{
	/// Pose of the current vehicle frame in the previous one, in metres.
	Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
	MotionQuality quality;  ///< of that motion (default: unknown)
};
}  // namespace vlo::kernel
