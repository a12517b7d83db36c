#include <vlo/loam/deskew.h>

#include <vlo/core/se3_twist.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace vlo::loam
{
void deskewTabulated(ScanPoints& points, const Eigen::Isometry3d& motion, double dt)
{
	// Exact transforms at 1024 time steps over the points' times, one trig evaluation per step, not
	// per point. Each point blends the two steps around its time: the nearest step alone was off by
	// up to 1/2048 of the span's motion (0.9 mm at 1.2 m per sweep); blended, the error is second
	// order in the step (micrometres).
	// Constant twist, not A-LOAM's scaled angle and chord (as the motion prior's): in a turn the sensor moves on
	// an arc, and the chord puts both ends of the sweep off it to the same side.
	constexpr int kSteps = 1024;
	if (points.empty() || !(dt > 0)) return;
	const Vector6d xi = logTwist(motion) / dt;  // per second
	float lo = points.front().time, hi = lo;
	for (const ScanPoint& p : points) lo = std::min(lo, p.time), hi = std::max(hi, p.time);
	if (!(hi > lo)) hi = lo + 1e-6f;
	std::array<Eigen::Matrix3f, kSteps + 1> R;
	std::array<Eigen::Vector3f, kSteps + 1> t;
	for (int k = 0; k <= kSteps; ++k)
	{
		const Eigen::Isometry3d T = expTwist((lo + static_cast<double>(hi - lo) * k / kSteps) * xi);
		R[k] = T.linear().cast<float>();
		t[k] = T.translation().cast<float>();
	}
	for (ScanPoint& p : points)
	{
		const float x = std::clamp((p.time - lo) / (hi - lo) * kSteps, 0.0f, static_cast<float>(kSteps));
		const int k = std::min(static_cast<int>(x), kSteps - 1);
		const float w = x - static_cast<float>(k);
		p.p = (1 - w) * (R[k] * p.p + t[k]) + w * (R[k + 1] * p.p + t[k + 1]);
	}
}
}  // namespace vlo::loam
