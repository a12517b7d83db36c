#pragma once
// Robust least-squares pose from line and plane matches: core's reweighted Levenberg-Marquardt
// (vlo/core/robust_pose_solver.h) with J^T W J accumulated in one pass over the matches.
#include <vlo/loam/correspondences.h>
#include <vlo/loam/options.h>
#include <vlo/loam/pose_prior.h>

#include <Eigen/Geometry>

namespace vlo::loam
{
struct SolveReport
{
	int iterations = 0;  ///< solver iterations (one reweighting and one step each)
	double rms = 0;  ///< RMS of the point-to-line/plane distances at the solution [m]
	Eigen::Matrix<double, 6, 6> JtJ = Eigen::Matrix<double, 6, 6>::Zero();  ///< robust-weighted, see Degeneracy
};

/// Refines T (source -> target) so that T * p lies on the matched lines and planes, and, with a
/// prior, near the prior's pose as its information says. The report's JtJ is the matches' alone.
SolveReport solvePose(const Matches& m, const SolverOptions& o, Eigen::Isometry3d& T, const PosePrior* prior = nullptr);

/// Whether a round moved the pose by less than the convergence thresholds.
bool roundConverged(const Eigen::Isometry3d& before, const Eigen::Isometry3d& after, const SolverOptions& o);

/// The robust-weighted J^T J and RMS distance of the matches at T (what solvePose reports).
void evaluateMatches(const std::vector<EdgeMatch>& edges, const std::vector<PlaneMatch>& planes, const SolverOptions& o,
	const Eigen::Isometry3d& T, Eigen::Matrix<double, 6, 6>& JtJ, double& rms);
}  // namespace vlo::loam
