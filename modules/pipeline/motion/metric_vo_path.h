#pragma once
// The scale-corrected visual odometry in metres (trajectory_vo.tum of mode vlo). The VO keeps its own
// trajectory continuous through rescaling, so its early segments stay in the units they were made
// in; this path instead chains each frame's camera motion once it is metric, and re-expresses the
// frames of a fresh map in metres when its first scale arrives.
#include <vlo/core/trajectory.h>
#include <vlo/kernel/scale_correction.h>
#include <vlo/kernel/visual_odometry.h>

#include <optional>
#include <utility>
#include <vector>

namespace vlo::pipeline
{
class MetricVoPath
{
   public:
	explicit MetricVoPath(const Eigen::Isometry3d& vehicle_T_camera) : Tvc_(vehicle_T_camera) {}

	/// Call once per frame with the VO's step and the scale corrector's decision at that frame (which
	/// the VO's map takes before the next). Returns the metric motion of the vehicle since the
	/// previous frame (the LiDAR odometry's initial guess) when it is known.
	std::optional<Eigen::Isometry3d> update(double t, const kernel::VisualOdometryStep& step, const kernel::ScaleCorrection& correction);

	/// Vehicle poses relative to the vehicle where the first map began, metres.
	const Trajectory& trajectory() const { return path_; }
	bool metric() const { return metric_; }

   private:
	Eigen::Isometry3d toVehicle(const Eigen::Isometry3d& camera) const { return Tvc_ * camera * Tvc_.inverse(); }
	void push(double t, const Eigen::Isometry3d& camera_pose);

	Eigen::Isometry3d Tvc_;
	std::optional<Eigen::Isometry3d> last_;  ///< metric camera pose of the last frame on the path
	Eigen::Isometry3d origin_ = Eigen::Isometry3d::Identity();  ///< metric pose of the current map's frame
	std::vector<std::pair<double, Eigen::Isometry3d>> pending_;  ///< map poses while the scale is unknown
	bool metric_ = false;
	Trajectory path_;
};
}  // namespace vlo::pipeline
