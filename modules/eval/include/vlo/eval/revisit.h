#pragma once
// The revisit error: where the ground truth comes back to a place it passed earlier, how far the
// estimate's relative pose between the two visits is from the truth's. What a loop closure corrects
// and an odometry's drift spoils, whatever the alignment (it is relative, like the RPE, but between
// poses far apart along the path and close in space).
#include <vlo/io/trajectory.h>

#include <cstddef>
#include <vector>

namespace vlo::eval
{
struct RevisitOptions
{
	/// Ground-truth positions at most this far apart (m, 3D) are the same place, in either direction of travel.
	double radius_m = 3;
	/// Path driven between the two visits (m, along the ground truth), so that neighbouring frames are no revisit.
	double min_path_m = 50;
};

struct RevisitPair
{
	std::size_t first = 0, second = 0;  ///< matched-pose indices, first < second
	double distance_m = 0;  ///< between the two ground-truth positions
	double t_err_m = 0, r_err_deg = 0;  ///< of (G_first^-1 G_second)^-1 (P_first^-1 P_second)
};

struct RevisitResult
{
	std::vector<RevisitPair> pairs;  ///< one per revisiting pose, in its order
	double t_rmse_m = 0, t_max_m = 0, r_rmse_deg = 0, r_max_deg = 0;  ///< 0 without pairs

	bool empty() const { return pairs.empty(); }
};

/// The revisits of a ground truth: for each pose j, the nearest earlier pose i within radius_m of it with at
/// least min_path_m of path between them (ties: the earlier i); poses without one have no pair. Errors are 0.
/// Throws std::invalid_argument when radius_m is not positive and finite.
std::vector<RevisitPair> findRevisits(const Trajectory& gt, const RevisitOptions& opts = {});

/// gt and est are pairs by index (see associate()), with full ground-truth poses: the revisits of gt and the
/// error of each estimated relative pose, with RMS and maximum over them.
RevisitResult computeRevisitError(const Trajectory& gt, const Trajectory& est, const RevisitOptions& opts = {});
}  // namespace vlo::eval
