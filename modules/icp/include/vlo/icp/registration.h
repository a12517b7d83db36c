#pragma once
// Point-to-point ICP of a scan against the voxel map (KISS-ICP paper, section III-D): each scan point
// is paired with its nearest map point within max_distance, and Gauss-Newton on SE(3) minimises the
// Geman-McClure-weighted squared distances, re-pairing after every step.
#include <vlo/icp/voxel_map.h>

#include <Eigen/Geometry>

namespace vlo::icp
{
struct RegistrationParams
{
	double max_distance = 6.0;  ///< correspondence gate [m] (3 sigma)
	double kernel = 0.8;  ///< Geman-McClure scale k [m]: residuals of k weigh 1/4
	int max_iterations = 500;
	double convergence = 1e-4;  ///< norm of the 6-vector update that ends the iterations
	std::size_t min_correspondences = 6;  ///< fewer: stop where we are
};

struct RegistrationResult
{
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< scan in the map
	int iterations = 0;
	std::size_t correspondences = 0;  ///< of the last iteration
	double rms = 0;  ///< of the last iteration's paired distances [m]
	/// Geman-McClure-weighted J^T J of the last iteration's pairs, over the left twist [translation;
	/// rotation] of the pose (the pose's information up to the residuals' variance).
	Eigen::Matrix<double, 6, 6> JtJ = Eigen::Matrix<double, 6, 6>::Zero();
	bool converged = false;
};

/// Geman-McClure weight of a residual of squared norm e2: (k^2 / (k^2 + e2))^2, 1 at e = 0.
double gemanMcClureWeight(double e2, double kernel);

/// Registers `scan` (sensor frame) to `map` starting from `guess` (sensor in map).
RegistrationResult alignToMap(
	const Points& scan, const VoxelMap& map, const Eigen::Isometry3d& guess, const RegistrationParams& params);
}  // namespace vlo::icp
