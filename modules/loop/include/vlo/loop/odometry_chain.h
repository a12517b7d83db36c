#pragma once
// The odometry's uncertainty between consecutive keyframes: each frame's motion with the covariance
// of its registration (the inverse of the information the LiDAR odometry gives), composed along the
// frames since the last keyframe to first order. On the odometry's thread: a few 6x6 products a frame.
#include <vlo/core/pose_information.h>
#include <vlo/loop/options.h>

#include <Eigen/Geometry>
#include <optional>

namespace vlo::loop
{
class OdometryChain
{
   public:
	explicit OdometryChain(const LoopOptions& options);

	/// A frame's motion since the previous frame (vehicle frame) and its information over the pose
	/// graph's [translation; rotation]: its covariance is the information's inverse plus the floor's
	/// per-metre model; nullopt (no registration): the odometry_sigma per-metre model.
	void add(const Eigen::Isometry3d& motion, const std::optional<Matrix6d>& information);
	/// The covariance of the motion since the last take() (or the first add), then starts anew.
	Matrix6d take();

   private:
	double floor_per_metre_, floor_rad_per_metre_, sigma_per_metre_, sigma_rad_per_metre_;
	Eigen::Isometry3d motion_ = Eigen::Isometry3d::Identity();
	Matrix6d covariance_ = Matrix6d::Zero();
};

/// The per-metre model's covariance of a motion over `distance` [m] (at least floor_distance):
/// sigma = per_metre x distance in translation [m] and rotation [rad].
Matrix6d distanceCovariance(
	double distance, double sigma_per_metre, double sigma_rad_per_metre, double floor_distance = 0.1);
}  // namespace vlo::loop
