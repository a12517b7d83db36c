#pragma once
// Module family "visual odometry": per frame, the vehicle's motion and pose from the camera, in the
// VO's own units (metres for a stereo or RGB-D VO, an arbitrary map scale for a monocular one).
// Created by name ([pipeline] visual_odometry) through registry<VisualOdometryModule>().
#include <vlo/core/frame.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/registry.h>
#include <vlo/kernel/run_config.h>

#include <Eigen/Geometry>
#include <optional>

namespace vlo
{
struct VisualOdometryStep
{
	bool tracked = false;  ///< false while initialising or LOST
	/// Vehicle pose relative to the vehicle at the first frame, when tracked.
	std::optional<Eigen::Isometry3d> pose;
	/// Motion of the vehicle since the previous frame (pose of the current vehicle frame in the
	/// previous one), when both frames were tracked.
	std::optional<Eigen::Isometry3d> motion;
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

/// What a monocular VO tells a scale corrector about the frame just processed, in the camera's
/// optical frame and map units.
struct MonocularState
{
	std::optional<Eigen::Isometry3d> camera_motion;  ///< current camera in the previous camera
	std::optional<Eigen::Isometry3d> camera_map_pose;  ///< camera in the current map's frame
	bool new_map = false;  ///< a map (of arbitrary scale) was initialised at this frame
};

/// A monocular VO, whose map has an unknown scale that a scale corrector sets and keeps metric.
class MonocularVisualOdometry : public VisualOdometryModule
{
   public:
	/// The state after the last process().
	virtual MonocularState monocular() const = 0;
	/// Multiplies the map's lengths by `factor`: about the map's origin when `whole_map` (the first,
	/// metric scale), else about the local window's earliest keyframe (a drift correction).
	/// False when there is nothing to scale.
	virtual bool rescale(double factor, bool whole_map) = 0;
};
}  // namespace vlo
