#pragma once
// A whole trajectory moved onto the ground truth by a similarity: how an unscaled (monocular) path is
// drawn beside metric ones.
#include <vlo/core/se3.h>
#include <vlo/io/trajectory.h>

#include <optional>

namespace vlo::eval
{
/// The Sim(3) that best maps the estimate's positions onto the ground truth's at the same times
/// (associate(), then umeyama() with scale); none when fewer than 3 poses pair up.
std::optional<Sim3> sim3ToGroundTruth(const Trajectory& gt, const Trajectory& est);

/// Each pose moved by S: a Sim(3) is not an isometry, so positions take the scale and orientations only
/// the rotation.
Trajectory transformed(Trajectory traj, const Sim3& S);
}  // namespace vlo::eval
