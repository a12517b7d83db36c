#pragma once
// Module family "LiDAR odometry": poses of the vehicle (not the sensor) and a map, with diagnostics
// written into the frame table. Created by name ([pipeline] lidar_odometry) through
// registry<LidarOdometryModule>().
#include <vlo/core/frame.h>
#include <vlo/core/pose_information.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/motion_guess.h>
#include <vlo/kernel/registry.h>
#include <vlo/kernel/run_config.h>
#include <vlo/kernel/sensor_mount.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>

namespace vlo::kernel
{
/// Where a LiDAR odometry that works in its sensor's frame meets the interface's vehicle frame: the
/// LiDAR's placement, taken from the first frame, moves guesses in and poses out.
class LidarMount : public SensorMount
{
   public:
	LidarMount() : SensorMount(&SensorRig::vehicle_T_lidar) {}
	/// A guessed motion of the vehicle seen from the LiDAR: L = Tvl^-1 * V * Tvl.
	std::optional<Eigen::Isometry3d> lidarMotion(const std::optional<MotionGuess>& guess) const
	{
		if (!guess) return std::nullopt;
		return vehicleTsensor().inverse() * guess->motion * vehicleTsensor();
	}
	/// The vehicle's pose relative to its first frame from the LiDAR's relative to its first frame.
	Eigen::Isometry3d vehiclePose(const Eigen::Isometry3d& lidar_pose) const
	{
		return vehicleTsensor() * lidar_pose * vehicleTsensor().inverse();
	}
	/// The information of the vehicle's motion from that of the LiDAR's motion `lidar_motion` (both
	/// over vlo/core/pose_information.h's delta, each in its own frame).
	Matrix6d vehicleInformation(const Matrix6d& lidar_information, const Eigen::Isometry3d& lidar_motion) const
	{
		return vehicleMotionInformation(lidar_information, vehicleTsensor(), vehiclePose(lidar_motion));
	}
};

/// What a LiDAR odometry gives for a frame.
struct LidarOdometryStep
{
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< vehicle, relative to the vehicle at the first frame
	/// Of the vehicle's motion since the previous frame (previous^-1 * pose), over the pose graph's
	/// [translation; rotation] (vlo/core/pose_information.h), from the frame's registration scaled
	/// by registrationInformation(); nullopt where the module has none (a frame not registered).
	std::optional<Matrix6d> information;
};

/// What a LiDAR odometry computed from a frame's scan alone, ahead of the frame's turn: each module
/// derives its own, and gets it back, to own, with the frame.
struct PreparedScan
{
	virtual ~PreparedScan() = default;
};

class LidarOdometryModule
{
   public:
	virtual ~LidarOdometryModule() = default;
	/// Loads and validates this module's options from the run configuration.
	virtual void configure(RunConfig& config) = 0;
	/// Work on the frame alone, ahead of process, maybe on another thread (the run's reader); its
	/// result comes back with the frame to process. Called once per frame, in frame order, from one
	/// thread at a time; it must touch nothing process uses, so that the results are the same
	/// whichever thread runs it. Default: nothing ahead (nullptr).
	virtual std::unique_ptr<PreparedScan> prepare(const Frame& /*frame*/) { return nullptr; }
	/// `prepared` is what prepare() made of this frame, or nullptr (then the module does that work
	/// itself). `guess` is an external guess of the vehicle's motion since the previous frame and
	/// its quality (a module may weigh the motion by it), or nullopt: the module then predicts on
	/// its own.
	virtual LidarOdometryStep process(const Frame& frame, std::unique_ptr<PreparedScan> prepared,
		const std::optional<MotionGuess>& guess, FrameTable& table) = 0;
};
}  // namespace vlo::kernel
