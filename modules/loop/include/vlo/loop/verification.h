#pragma once
// Geometric verification of a place candidate: the current keyframe's scan registered against the
// candidate's submap from the descriptor's yaw, then three gates, each for a way a false loop passes
// the others: too few inliers (another place), a degenerate registration (a corridor slides along its
// axis), and too large a correction for the path driven in between (a repeated place elsewhere: a
// street of identical facades registers perfectly, but the odometry cannot have drifted that far).
#include <vlo/loop/keyframe.h>
#include <vlo/loop/loop_closure.h>
#include <vlo/loop/options.h>
#include <vlo/loop/point_to_plane.h>
#include <vlo/loop/scan_context.h>

#include <optional>
#include <vector>

namespace vlo::loop
{
/// Keyframes [center - half, center + half] (clamped to [0, end)) moved into keyframe `center`'s
/// vehicle frame with the odometry's poses.
icp::Points candidateSubmap(const std::vector<Keyframe>& keyframes, std::size_t center, int half, std::size_t end);

struct Verification
{
	LoopRecord record;  ///< frames, descriptor, registration, gates' figures, accepted or why not
	Matrix6d information = Matrix6d::Zero();  ///< of the loop edge (pose graph residual), when accepted
};

/// The drift gate's limit [m] for `path_between` metres of odometry between the visits.
double maxDrift(double path_between, const LoopOptions& options);

/// A candidate that the odometry puts farther away than the drift gate allows plus what a
/// registration from the descriptor's guess (the same position) can reach: rejected for its drift
/// without registering (a repeated place elsewhere, most candidates of a drive without revisits).
std::optional<Verification> rejectOutOfReach(const DescriptorMatch& match,
	const Eigen::Isometry3d& odometry_candidate_T_current, double path_between, const LoopOptions& options);

/// `odometry_candidate_T_current`: the relative pose the odometry gives; `path_between` [m]: the
/// odometry's path from the candidate to the current keyframe.
Verification verifyLoop(const ScanPoints& current, const icp::Points& submap, const DescriptorMatch& match,
	const Eigen::Isometry3d& odometry_candidate_T_current, double path_between, const LoopOptions& options);
}  // namespace vlo::loop
