#pragma once
// What the run loop needs of a monocular visual odometry: per frame, the vehicle's motion and pose
// (up to the map's scale), a tracking state, and what the scale corrector reads and corrects (camera
// motion, map pose, rescaling). Created by name through visualOdometryRegistry().
#include <vlo/core/frame.h>
#include <vlo/pipeline/frame_table.h>
#include <vlo/pipeline/registry.h>
#include <vlo/pipeline/run_config.h>

#include <Eigen/Geometry>
#include <optional>

namespace vlo
{
struct VisualOdometryStep
{
	bool tracked = false;  ///< false while initialising or LOST
	/// Vehicle pose relative to the vehicle at the first frame (map scale), when tracked.
	std::optional<Eigen::Isometry3d> pose;
	/// Motion of the vehicle since the previous frame (pose of the current vehicle frame in the
	/// previous one, map scale), when both frames were tracked.
	std::optional<Eigen::Isometry3d> motion;

	// For the scale corrector, in the camera's optical frame and map units.
	std::optional<Eigen::Isometry3d> camera_motion;  ///< current camera in the previous camera
	std::optional<Eigen::Isometry3d> camera_map_pose;  ///< camera in the current map's frame
	bool new_map = false;  ///< a map (of arbitrary scale) was initialised at this frame
	bool metric = false;  ///< the map's scale was set: map units are metres
};

class VisualOdometryModule
{
   public:
	virtual ~VisualOdometryModule() = default;
	/// Loads and validates this module's options from the run configuration.
	virtual void configure(RunConfig& config) = 0;
	/// Tracks one frame (only its image and rig are used) and writes its diagnostics columns.
	virtual VisualOdometryStep process(const Frame& frame, FrameTable& table) = 0;
	/// Multiplies the map's lengths by `factor`: the whole map about its origin when `whole_map` (the
	/// first, metric scale), else the local window about its earliest keyframe (a drift correction).
	/// False when there is nothing to scale.
	virtual bool rescale(double factor, bool whole_map) = 0;
};

Registry<VisualOdometryModule>& visualOdometryRegistry();
}  // namespace vlo
