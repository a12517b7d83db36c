#pragma once
// What the run loop needs of a LiDAR odometry: poses of the vehicle (not the sensor) and a map,
// with its diagnostics written into the frame table. Created by name through lidarOdometryRegistry().
#include <vlo/core/frame.h>
#include <vlo/pipeline/frame_table.h>
#include <vlo/pipeline/registry.h>
#include <vlo/pipeline/run_config.h>

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
	/// `vehicle_motion` is an external guess of the vehicle's motion since the previous frame (pose of
	/// the current vehicle frame in the previous one), or nullopt. Returns the vehicle pose relative
	/// to the vehicle at the first frame.
	virtual Eigen::Isometry3d process(
		const Frame& frame, const std::optional<Eigen::Isometry3d>& vehicle_motion, FrameTable& table) = 0;
};

Registry<LidarOdometryModule>& lidarOdometryRegistry();
/// KISS-ICP's method (modules/icp), registered as "icp".
std::unique_ptr<LidarOdometryModule> makeIcpModule();
}  // namespace vlo
