#pragma once
// One top-down picture per sequence: every configuration's trajectories against the ground truth.
#include <vlo/batch/plan.h>
#include <vlo/batch/results.h>

#include <string>
#include <vector>

namespace vlo::batch
{
/// Writes OUT/snapshots/SEQUENCE.png for each sequence with at least one trajectory and returns their
/// paths relative to OUT. A picture that cannot be drawn is a warning on stderr, not an error.
std::vector<std::string> writeSnapshots(
	const Plan& plan, const std::vector<RunResult>& results, const std::string& out);
}  // namespace vlo::batch
