#pragma once
// Point-to-plane ICP of a scan against a PlaneMap (Gauss-Newton, Geman-McClure weights), the fine
// stage of a loop's verification, and the information of its result: what the loop edge weighs and
// what tells a corridor (no constraint along it) from a place.
#include <vlo/core/pose_information.h>
#include <vlo/core/se3_twist.h>
#include <vlo/loop/plane_map.h>

#include <Eigen/Geometry>

namespace vlo::loop
{
struct PlaneFit
{
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< scan in the map
	/// Sum over the pairs of J^T J, J = n^T [I, -[R p]x]: in the perturbation t + dt, exp(dtheta) R, the
	/// pose graph's residual [translation; rotation]. Unit weights: scaled by the caller.
	Matrix6d information = Matrix6d::Zero();
	std::size_t pairs = 0;  ///< scan points paired with a plane within the last gate
	double rms = 0;  ///< [m] of the pairs' point-to-plane distances
	int iterations = 0;
};

/// Registers `scan` to `map` from `guess`, pairing each point with the plane of its nearest map point
/// within `gate` [m]; `kernel` is the Geman-McClure scale [m].
PlaneFit alignPointToPlane(const icp::Points& scan, const PlaneMap& map, const Eigen::Isometry3d& guess, double gate,
	double kernel, int max_iterations);

/// Smallest over largest eigenvalue of the translation block: 0 when a direction is unconstrained.
double translationConstraint(const Matrix6d& information);
}  // namespace vlo::loop
