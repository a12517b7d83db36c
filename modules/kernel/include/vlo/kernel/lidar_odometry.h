#pragma once
// Module family "LiDAR odometry": poses of the vehicle (not the sensor) and a map, with diagnostics
// written into the frame table. Created by name ([pipeline] lidar_odometry) through
// registry<LidarOdometryModule>().
#include <vlo/core/frame.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/registry.h>
#include <vlo/kernel/run_config.h>

#include <Eigen/Geometry>
#include <optional>

namespace vlo
{
class LidarOdometryModule
{
   public:
	virtual ~LidarOdometryModule() = default;
	/// Loads and validates this module's options from the run configuration.
	virtual void configure(RunConfig& config) = 0;
	/// `vehicle_motion` is an external guess of the vehicle's motion since the previous frame, in
	/// metres (pose of the current vehicle frame in the previous one), or nullopt: the module then
	/// predicts on its own. Returns the vehicle pose relative to the vehicle at the first frame.
	virtual Eigen::Isometry3d process(
		const Frame& frame, const std::optional<Eigen::Isometry3d>& vehicle_motion, FrameTable& table) = 0;
};
}  // namespace vlo
