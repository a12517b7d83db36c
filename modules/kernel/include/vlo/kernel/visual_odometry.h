#pragma once
// Module family "visual odometry": per frame, the camera's pose and motion in the VO's own units
// (metres for a stereo or RGB-D VO, an arbitrary map scale for a monocular one), one result a frame.
// The motion source places the camera on the vehicle (CameraMount). Created by name
// ([pipeline] visual_odometry) through registry<VisualOdometryModule>().
#include <vlo/core/frame.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/registry.h>
#include <vlo/kernel/run_config.h>
#include <vlo/kernel/sensor_mount.h>

#include <Eigen/Geometry>
#include <optional>

namespace vlo::kernel
{
/// What a visual odometry tells of one frame, in the camera's optical frame and the VO's units.
struct VisualOdometryStep
{
	/// Camera pose relative to the camera where the VO began, when tracked.
	std::optional<Eigen::Isometry3d> camera_pose;
	/// Pose of the current camera in the previous one, when both frames were tracked in one map.
	std::optional<Eigen::Isometry3d> camera_motion;
	/// Camera pose in the current map's frame, when tracked: what scaling the whole map scales.
	std::optional<Eigen::Isometry3d> camera_map_pose;
	bool new_map = false;  ///< a map (of arbitrary scale for a monocular VO) was initialised at this frame
	bool metric = false;  ///< the units are metres (a monocular VO's: once its map was scaled)
	std::optional<int> tracked;  ///< image features tracked in the map at this frame, when the VO counts them
};

/// Where the camera sits on the vehicle, taken from the first frame: turns the VO's camera poses and
/// motions into the vehicle's.
class CameraMount : public SensorMount
{
   public:
	CameraMount() : SensorMount(&SensorRig::vehicle_T_camera) {}
	/// A camera pose or motion C seen from the vehicle: V = Tvc * C * Tvc^-1. The lever arm of Tvc is
	/// in metres: in units that are not (`metric` false) it is left out (the camera's path in vehicle
	/// axes), or it would bend the path by (I - R) t_vc against motions in map units.
	Eigen::Isometry3d vehicle(const Eigen::Isometry3d& camera, bool metric) const
	{
		Eigen::Isometry3d Tvc = vehicleTsensor();
		if (!metric) Tvc.translation().setZero();
		return Tvc * camera * Tvc.inverse();
	}
};

class VisualOdometryModule
{
   public:
	virtual ~VisualOdometryModule() = default;
	/// Loads and validates this module's options from the run configuration.
	virtual void configure(RunConfig& config) = 0;
	/// The threads the run may use (1 or 2): a module may then work beside its caller, at fixed frames
	/// so that its results do not change.
	virtual void useThreads(int /*threads*/) {}
	/// Tracks one frame (its image and rig) and writes its diagnostics columns.
	virtual VisualOdometryStep process(const Frame& frame, FrameTable& table) = 0;
};

/// A monocular VO, whose map has an unknown scale that a scale corrector sets and keeps metric.
class MonocularVisualOdometry : public VisualOdometryModule
{
   public:
	/// Multiplies the map's lengths by `factor`, between frames: about the map's origin when
	/// `whole_map` (the first, metric scale), else about the local window's earliest keyframe (a
	/// drift correction). False when there is nothing to scale (no map).
	virtual bool rescale(double factor, bool whole_map) = 0;
};
}  // namespace vlo::kernel
