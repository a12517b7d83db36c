#pragma once
// Absolute trajectory and rotation errors (ATE / ARE) of an estimate against time-associated ground
// truth, after aligning the estimate with a closed-form Umeyama fit.
#include <vlo/core/se3.h>
#include <vlo/io/trajectory.h>

#include <optional>
#include <string>
#include <vector>

namespace vlo::eval
{
enum class Alignment
{
	None,  ///< compare as given (both trajectories share the first frame by convention)
	SE3,  ///< rigid: the estimate's frame is arbitrary
	Sim3  ///< similarity: also its scale (unscaled monocular output)
};
/// "none" | "se3" | "sim3"; throws InputError naming `where` otherwise.
Alignment parseAlignment(const std::string& s, const std::string& where = "--align");
const char* toString(Alignment a);

struct AteResult
{
	Sim3 alignment;  ///< applied to the estimate: aligned_i = alignment * est_i
	double ate_rmse_m = 0, ate_mean_m = 0, ate_max_m = 0;
	/// The aligned estimate's position error RMS along each axis of the ground truth's own frame at each
	/// pose (a vehicle frame: along the way, across it, up), so that an error the truth itself makes in one
	/// direction (e.g. a GNSS track's lateral wander) is told apart; empty for translation-only truth.
	std::optional<Eigen::Vector3d> ate_rmse_axes_m;
	std::optional<double> are_rmse_deg;  ///< empty when the ground truth has no rotations
	/// Set when the path is nearly straight and too straight for the positions to fix the alignment's rotation
	/// about the direction of travel (uncertain by more than 1 deg): the ARE then takes that rotation from the
	/// orientations, and this is how far it turned the positions' choice (deg). ATE and `alignment` keep the
	/// positions' fit.
	std::optional<double> are_roll_from_orientations_deg;
	double are_roll_uncertainty_deg = 0;  ///< of the positions' fit, about the direction of travel
	/// Scale of the best Sim(3) fit, whatever the alignment applied; empty when the estimate does not move.
	std::optional<double> sim3_scale;
	std::size_t n = 0;
};

/// gt and est are pairs by index (see associate()), at least 3 of them. ARE uses the rotation angle of
/// G_i^-1 * A * P_i (A's rotation about a straight path's direction from the orientations, see AteResult);
/// pass gt_has_rotation = false for translation-only ground truth.
AteResult computeAte(const Trajectory& gt, const Trajectory& est, Alignment align, bool gt_has_rotation = true);

/// Each pair's position error |g_i - alignment * p_i| (m): what ATE statistics summarise, e.g. to colour a path.
std::vector<double> ateErrors(const Trajectory& gt, const Trajectory& est, const Sim3& alignment);
}  // namespace vlo::eval
