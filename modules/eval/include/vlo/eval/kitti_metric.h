#pragma once
// The KITTI odometry benchmark metric, as the devkit's evaluate_odometry.cpp computes it: relative
// pose errors over path segments of fixed lengths measured along the ground truth.
#include <vlo/io/trajectory.h>

#include <cstddef>
#include <vector>

namespace vlo::eval
{
struct KittiOptions
{
	std::vector<double> lengths{100, 200, 300, 400, 500, 600, 700, 800};  ///< metres
	std::size_t step = 10;  ///< first frames every `step` frames (1 s at 10 Hz)
};

struct KittiSegment
{
	std::size_t first = 0, last = 0;
	double length = 0;  ///< nominal length (one of the options' lengths)
	double t_err = 0;  ///< ||translation of the error|| / length (m/m)
	double r_err = 0;  ///< rotation angle of the error / length (rad/m)
	/// m/s: length / ((last - first + 1) * median frame period), the devkit's formula (which assumes 0.1 s);
	/// NAN when the ground truth has no increasing timestamps.
	double speed = 0;
};

struct KittiLengthStats
{
	double length = 0;
	std::size_t n = 0;
	double t_err = 0, r_err = 0;  ///< means over this length's segments (m/m, rad/m)
};

struct KittiResult
{
	std::vector<KittiSegment> segments;
	std::vector<KittiLengthStats> per_length;  ///< only lengths with at least one segment
	double t_err = 0, r_err = 0;  ///< means pooled over all segments (m/m, rad/m); 0 when none

	bool empty() const { return segments.empty(); }
};

/// gt and est are pairs by index (see associate()), in the frame the metric is wanted in (KITTI
/// uses camera 0; the translation error depends on that choice). Both are plain pose sequences:
/// frame i of one matches frame i of the other.
KittiResult kittiMetric(const Trajectory& gt, const Trajectory& est, const KittiOptions& opts = {});

/// Cumulative distance along the positions: dist[0] = 0, dist[i] = dist[i-1] + |p_i - p_{i-1}|.
std::vector<double> trajectoryDistances(const Trajectory& traj);
}  // namespace vlo::eval
