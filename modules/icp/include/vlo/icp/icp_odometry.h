#pragma once
// KISS-ICP's odometry composed from its parts: predict the motion (constant velocity, or an external
// guess such as the VO's), deskew and preprocess the scan, register it to the local voxel map with
// the adaptive threshold, then update the threshold and the map. Poses are of the LiDAR sensor.
//
//   IcpOdometry odo(options);
//   for (each scan) { auto r = odo.process(t, scan, guess_or_nullopt); use r.pose; }
#include <vlo/core/frame.h>
#include <vlo/core/lidar_frame_status.h>
#include <vlo/core/stage_times.h>
#include <vlo/icp/adaptive_threshold.h>
#include <vlo/icp/deskew.h>
#include <vlo/icp/options.h>
#include <vlo/icp/registration.h>
#include <vlo/icp/voxel_map.h>

#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace vlo::icp
{
struct IcpResult
{
	double t = 0;
	LidarFrameStatus status = LidarFrameStatus::Skipped;  ///< Ok, Initialized or Skipped
	std::string reason;  ///< empty when Ok
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< sensor in the first sensor frame
	Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();  ///< pose of this frame in the previous
	std::string prediction;  ///< constant_velocity | external
	bool deskewed = false;  ///< undistorted with the scan's point times
	std::size_t n_input = 0, n_valid = 0, n_source = 0;  ///< given / in range / registered (downsampled)
	RegistrationResult registration;
	double sigma = 0;  ///< adaptive threshold used [m]
	double model_error = 0;  ///< of this frame's prediction [m]
	std::size_t map_points = 0;
	/// features (preprocessing), mapping (registration and map update)
	StageTimes ms{{"features", "mapping"}};
};

class IcpOdometry
{
   public:
	/// Validates the options (throws InputError naming the bad key).
	explicit IcpOdometry(const IcpOptions& options);

	/// `guess`: an external estimate of this frame's motion (pose of this sensor frame in the previous
	/// one); it replaces the constant-velocity prediction when given and plausible.
	IcpResult process(double t, const PointCloud& scan, const std::optional<Eigen::Isometry3d>& guess);

	const VoxelMap& map() const { return map_; }

   private:
	Eigen::Isometry3d predict(const std::optional<Eigen::Isometry3d>& guess, IcpResult& r) const;

	IcpOptions opt_;
	VoxelMap map_;
	AdaptiveThreshold threshold_;
	Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity(), velocity_ = Eigen::Isometry3d::Identity();
	double last_t_ = 0;
	bool started_ = false;
};
}  // namespace vlo::icp
