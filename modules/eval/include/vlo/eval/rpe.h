#pragma once
// Relative pose error between consecutive matched poses (the TUM benchmark's RPE with a step of one
// pose): how well each frame-to-frame motion is estimated, whatever the drift. Beside it, the same
// error for a constant-velocity prediction of the ground truth (each step predicted by the one
// before): what an odometry's initial guess would miss if it assumed constant velocity.
#include <vlo/io/trajectory.h>

#include <Eigen/Core>

namespace vlo::eval
{
struct RpeResult
{
	double t_rmse_m = 0, r_rmse_deg = 0;
	/// Translation error RMS per axis of the earlier pose's frame (vehicle: x forward, y left, z up).
	Eigen::Vector3d t_rmse_axes_m = Eigen::Vector3d::Zero();
	/// Constant velocity on the ground truth: step i+1 predicted by step i.
	double cv_t_rmse_m = 0, cv_r_rmse_deg = 0;
	std::size_t n = 0;  ///< steps compared
};

/// gt and est are pairs by index (see associate()), at least 3 of them, with full ground-truth poses.
RpeResult computeRpe(const Trajectory& gt, const Trajectory& est);
}  // namespace vlo::eval
