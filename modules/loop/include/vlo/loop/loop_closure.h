#pragma once
// Loop closure over the LiDAR odometry: keyframes every few metres, each with its thinned, de-skewed
// scan and a Scan Context descriptor; candidates found by descriptor among keyframes visited long ago,
// verified by registration against the candidate's submap, and a pose graph over the keyframes
// optimised with Ceres. The keyframes are handled on a thread of their own, at low priority: the
// odometry that calls addFrame never waits for them. Each keyframe is searched only among the
// keyframes before it, from the odometry's poses, so the loops found do not depend on the timing.
#include <vlo/core/frame.h>
#include <vlo/core/pose_information.h>
#include <vlo/core/trajectory.h>
#include <vlo/loop/options.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vlo::loop
{
/// A candidate found by the descriptor and what the verification made of it.
struct LoopRecord
{
	long long frame = -1;  ///< the current keyframe's frame index
	long long candidate_frame = -1;  ///< the earlier keyframe's frame index
	double descriptor_distance = 0;  ///< Scan Context distance, 0 (same) to 1
	double yaw_deg = 0;  ///< the descriptor's yaw of the current scan in the candidate's
	double inlier_fraction = 0;  ///< after registration (0 when not registered)
	double rms = 0;  ///< of the inliers [m]
	double constraint = 0;  ///< weakest over strongest direction of the registration's translation
	double drift = 0;  ///< [m] the correction the loop implies (odometry vs registration)
	double path_between = 0;  ///< [m] of odometry from the candidate to the current keyframe
	bool accepted = false;
	std::string reason;  ///< why it was rejected; empty when accepted
	Eigen::Isometry3d candidate_T_current = Eigen::Isometry3d::Identity();  ///< the registration's
};

class LoopClosure
{
   public:
	explicit LoopClosure(const LoopOptions& options);
	~LoopClosure();  ///< stops the loop thread
	LoopClosure(const LoopClosure&) = delete;
	LoopClosure& operator=(const LoopClosure&) = delete;

	/// Every frame of the odometry, in order: its pose (vehicle in the odometry's world), the
	/// information of its motion since the previous frame (kernel::LidarOdometryStep's; nullopt: the
	/// per-metre model) and its scan (LiDAR frame, with point times when it has them). Returns
	/// quickly: the covariance is composed towards the next keyframe's odometry edge, a keyframe's
	/// scan is copied and queued; the loop thread thins it and de-skews it with the odometry's motion.
	void addFrame(long long frame, double t, const Eigen::Isometry3d& world_T_vehicle,
		const std::optional<Matrix6d>& information, const PointCloud& scan, const Eigen::Isometry3d& vehicle_T_lidar);

	/// Waits until the loop thread handled every keyframe, then optimises the whole graph once more.
	void finish();

	/// After finish(): each added frame's pose corrected by the pose graph, in order (the odometry's
	/// own until the first loop).
	Trajectory corrected() const;
	/// After finish(): every candidate verified, accepted or not, in the order found.
	const std::vector<LoopRecord>& loops() const;
	std::size_t keyframes() const;
	/// After finish(): the final optimisation's wall time [s].
	double finalOptimisationSeconds() const;

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};
}  // namespace vlo::loop
