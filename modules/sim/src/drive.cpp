#include <vlo/core/se3.h>
#include <vlo/sim/drive.h>
#include <vlo/sim/rng.h>
#include <vlo/sim/road.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
constexpr double kDt = 0.01;

/// Target speeds: a new random cruise speed every 4-12 s.
struct SpeedPlan
{
	std::vector<std::pair<double, double>> changes;  // (time, target)
	double target(double t) const
	{
		double v = changes.front().second;
		for (const auto& c : changes)
			if (c.first <= t) v = c.second;
		return v;
	}
};

SpeedPlan planSpeeds(const DriveStyle& st, double duration, uint64_t seed)
{
	Rng rng = Rng::stream(seed, "speed plan");
	SpeedPlan p;
	for (double t = 0; t <= duration + 12; t += rng.uniform(4, 12)) p.changes.push_back({t, rng.uniform(st.v_min, st.v_max)});
	return p;
}

/// One step of a speed controller with acceleration and jerk limits.
void step(double target, const DriveStyle& st, double& v, double& a)
{
	constexpr double kJerk = 2.0;
	const double want = std::clamp(0.8 * (target - v), -st.a_max, st.a_max);
	a += std::clamp(want - a, -kJerk * kDt, kJerk * kDt);
	v = std::max(0.5, v + a * kDt);
}

/// The speed from which every bend in the next 120 m can still be taken at the lateral limit, braking
/// at half the comfortable deceleration after 1.5 s (the speed controller lags behind its target).
double bendSpeed(const Road& road, const DriveStyle& st, double s, double v)
{
	double limit = 1e9;
	for (double ds = 0; ds <= 120; ds += 1)
	{
		const double k = std::abs(road.at(s + ds).curvature);
		if (k < 1e-6) continue;
		const double room = std::max(0.0, ds - 1.5 * v);
		limit = std::min(limit, std::sqrt(st.lateral_a_max / k + st.a_max * room));
	}
	return std::max(st.bend_v_min, limit);
}
}  // namespace

VehicleMotion::VehicleMotion(Trajectory samples) : samples_(std::move(samples)) {}

Eigen::Isometry3d VehicleMotion::pose(double t) const
{
	const auto& s = samples_;
	if (s.size() == 1) return s.front().pose;
	auto extrapolate = [](const StampedPose& a, const StampedPose& b, double t) {
		// Repeat the relative motion of the end interval (constant velocity).
		const double f = (t - b.t) / (b.t - a.t);
		const Eigen::Isometry3d d = a.pose.inverse() * b.pose;
		const Eigen::AngleAxisd aa(d.rotation());
		Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
		step.linear() = Eigen::AngleAxisd(aa.angle() * f, aa.axis()).toRotationMatrix();
		step.translation() = d.translation() * f;
		return Eigen::Isometry3d(b.pose * step);
	};
	if (t <= s.front().t) return extrapolate(s[1], s[0], t);
	if (t >= s.back().t) return extrapolate(s[s.size() - 2], s.back(), t);
	const auto it = std::upper_bound(s.begin(), s.end(), t, [](double v, const StampedPose& p) { return v < p.t; });
	const StampedPose& b = *it;
	const StampedPose& a = *(it - 1);
	return interpolate(a.pose, b.pose, (t - a.t) / (b.t - a.t));
}

double plannedDistance(const DriveStyle& style, double duration, uint64_t seed)
{
	const SpeedPlan plan = planSpeeds(style, duration, seed);
	double v = plan.target(0), a = 0, d = 0;
	for (double t = 0; t < duration; t += kDt) step(plan.target(t), style, v, a), d += v * kDt;
	return d;
}

VehicleMotion driveAlong(const Road& road, const DriveStyle& style, double s0, double duration, uint64_t seed)
{
	const SpeedPlan plan = planSpeeds(style, duration, seed);
	Rng rng = Rng::stream(seed, "lane weave");
	const double weaveAmp = rng.uniform(0.1, 0.25), weavePeriod = rng.uniform(6, 12), weavePhase = rng.uniform(0, 6.3);
	double v = plan.target(0), a = 0, s = s0;
	if (style.brake_for_bends) v = std::min(v, bendSpeed(road, style, s, 0));
	Trajectory out;
	const int n = static_cast<int>(std::ceil(duration / kDt)) + 1;
	for (int i = 0; i < n; ++i)
	{
		const double t = i * kDt;
		// Slow down ahead of bends: the sharpest bend in the next 40 m limits the target.
		double kmax = 0;
		for (double ds = 0; ds <= 40 && !style.brake_for_bends; ds += 5) kmax = std::max(kmax, std::abs(road.at(s + ds).curvature));
		const double vcurve = kmax > 1e-6 ? std::sqrt(style.lateral_a_max / kmax) : 1e9;
		const double vbend = style.brake_for_bends ? bendSpeed(road, style, s, v) : std::max(style.v_min, vcurve);
		const Station st = road.at(s);
		const double lat = style.lane_offset + weaveAmp * std::sin(2 * M_PI * t / weavePeriod + weavePhase);
		const double dlat = weaveAmp * 2 * M_PI / weavePeriod * std::cos(2 * M_PI * t / weavePeriod + weavePhase) / v;
		const double yaw = st.heading + std::atan(dlat);
		const double pitch = -std::atan(st.grade) - 0.005 * a;  // nose up uphill, down when braking
		const double roll = 0.004 * v * v * st.curvature;  // leans out of the bend
		StampedPose p;
		p.t = t;
		p.pose = Eigen::Isometry3d::Identity();
		p.pose.translation() = road.point(s, lat);
		p.pose.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
			Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
							  .toRotationMatrix();
		out.push_back(p);
		step(std::min(plan.target(t), vbend), style, v, a);
		s += v * kDt;
	}
	return VehicleMotion(std::move(out));
}
}  // namespace vlo::sim
