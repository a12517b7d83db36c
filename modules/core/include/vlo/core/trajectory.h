#pragma once
// A trajectory: poses in time, as every estimator reports them (files: vlo/io/trajectory.h).
#include <Eigen/Geometry>
#include <vector>

namespace vlo
{
struct StampedPose
{
	double t = 0;
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};
using Trajectory = std::vector<StampedPose>;

/// Re-expresses every pose relative to the first one (first pose becomes identity).
Trajectory relativeToFirst(const Trajectory& traj);
/// Sum of distances between consecutive positions.
double pathLength(const Trajectory& traj);
}  // namespace vlo
