#pragma once
// The curves of the KITTI devkit's error plots (evaluate_odometry.cpp, saveErrorPlots): the mean
// segment errors against segment length and against driving speed.
#include <vlo/eval/kitti_metric.h>

#include <cstddef>
#include <vector>

namespace vlo::eval
{
struct KittiCurvePoint
{
	double x = 0;  ///< segment length (m) or speed (m/s)
	double t_err = 0, r_err = 0;  ///< means over the segments of this point (m/m, rad/m)
	std::size_t n = 0;  ///< segments averaged
};

struct KittiCurves
{
	std::vector<KittiCurvePoint> by_length;  ///< one point per length that has at least 3 segments
	/// Speeds 2, 4, ..., 24 m/s; each point averages the segments within 2 m/s of it (so neighbouring
	/// points share segments, as in the devkit) and is kept when it has at least 3 of them.
	std::vector<KittiCurvePoint> by_speed;

	bool empty() const { return by_length.empty() && by_speed.empty(); }
};

KittiCurves kittiCurves(const KittiResult& r, const KittiOptions& opts = {});
}  // namespace vlo::eval
