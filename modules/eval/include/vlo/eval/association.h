#pragma once
// Pairs every estimated pose with the ground truth at the same instant, interpolating the ground
// truth between its two bracketing samples, so that a slower ground truth (1 Hz RTK against a
// 10 Hz estimate) still gives one pair per estimated pose.
#include <vlo/io/trajectory.h>

#include <cstddef>

namespace vlo::eval
{
struct AssociationOptions
{
	/// Largest ground-truth interval (s) to interpolate across; an estimate falling in a wider gap
	/// is dropped. <= 0 selects 3x the median ground-truth spacing.
	double max_gap_s = 0;
	/// Estimates this close (s) outside the ground truth's span snap to its end sample, so that
	/// timestamps that went through a lossy round trip are not lost at the ends.
	double end_tolerance_s = 1e-6;
};

struct Association
{
	Trajectory est;  ///< matched estimated poses, in time order
	Trajectory gt;  ///< ground truth at the same times (interpolated), same size as est
	std::size_t n_est = 0, n_gt = 0;
	std::size_t n_outside_span = 0;  ///< estimates before the first or after the last GT sample
	std::size_t n_in_gap = 0;  ///< estimates inside a GT interval wider than max_gap_used_s
	double max_gap_used_s = 0;

	std::size_t matched() const { return est.size(); }
};

/// Never throws for lack of overlap (the result is then empty); throws InputError when either
/// trajectory's timestamps are not strictly increasing.
Association associate(const Trajectory& gt, const Trajectory& est, const AssociationOptions& opts = {});

/// Median spacing of consecutive timestamps (0 for fewer than two poses).
double medianTimeStep(const Trajectory& traj);
}  // namespace vlo::eval
