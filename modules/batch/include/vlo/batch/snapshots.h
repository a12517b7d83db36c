#pragma once
// One top-down picture per sequence: every configuration's trajectories against the ground truth.
#include <vlo/batch/plan.h>
#include <vlo/batch/results.h>
#include <vlo/viz/topdown.h>

#include <string>
#include <vector>

namespace vlo::batch
{
/// What a sequence's picture draws: each run's trajectories, labelled "config / name", a monocular one
/// Sim(3)-aligned. A run's trajectory identical to one of its own before it (the loop-closed one of a
/// run that closed no loop is its odometry's) is left out: drawn on top, it would hide that one.
std::vector<viz::NamedTrajectory> sequenceTrajectories(const Sequence& s, const std::vector<RunResult>& results);

/// Writes OUT/snapshots/SEQUENCE.png for each sequence with at least one trajectory and returns their
/// paths relative to OUT. A picture that cannot be drawn is a warning on stderr, not an error.
std::vector<std::string> writeSnapshots(
	const Plan& plan, const std::vector<RunResult>& results, const std::string& out);
}  // namespace vlo::batch
