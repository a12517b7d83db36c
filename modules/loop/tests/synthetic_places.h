#pragma once
// Synthetic places for the loop closure's tests: worlds of surfaces sampled at random points (a city
// of boxes and poles, a corridor, a street of identical facades), scans of them taken from a pose
// (every world point within range, with noise, a different random half each time: no occlusion), and
// drives whose odometry is given a known drift.
#include <vlo/core/frame.h>
#include <vlo/core/trajectory.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

namespace vlo::loop::test
{
using World = std::vector<Eigen::Vector3d>;

inline Eigen::Isometry3d pose2d(double x, double y, double yaw)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	T.translation() = Eigen::Vector3d(x, y, 0);
	return T;
}

/// Points on the rectangle o + [0,1] a + [0,1] b, `density` per square metre.
inline void addRectangle(World& w, std::mt19937& rng, const Eigen::Vector3d& o, const Eigen::Vector3d& a,
	const Eigen::Vector3d& b, double density)
{
	std::uniform_real_distribution<double> u(0, 1);
	const auto n = static_cast<int>(a.cross(b).norm() * density);
	for (int i = 0; i < n; ++i) w.push_back(o + u(rng) * a + u(rng) * b);
}

/// The four walls and the roof of a box on the ground.
inline void addBox(World& w, std::mt19937& rng, const Eigen::Vector3d& lo, const Eigen::Vector3d& size, double density)
{
	const Eigen::Vector3d ex(size.x(), 0, 0), ey(0, size.y(), 0), ez(0, 0, size.z());
	addRectangle(w, rng, lo, ey, ez, density);
	addRectangle(w, rng, lo + ex, ey, ez, density);
	addRectangle(w, rng, lo, ex, ez, density);
	addRectangle(w, rng, lo + ey, ex, ez, density);
	addRectangle(w, rng, lo + ez, ex, ey, density);
}

inline void addGround(World& w, std::mt19937& rng, double x0, double x1, double y0, double y1, double density)
{
	addRectangle(w, rng, {x0, y0, 0}, {x1 - x0, 0, 0}, {0, y1 - y0, 0}, density);
}

/// Ground, and boxes (buildings, cars) and poles at random, none within `clear` of the drive's path.
template <class OnPath>
World randomCity(unsigned seed, double x0, double x1, double y0, double y1, int objects, OnPath near_path)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1), u(0, 1);
	World w;
	addGround(w, rng, x0, x1, y0, y1, 0.5);
	for (int placed = 0; placed < objects;)
	{
		const Eigen::Vector3d size(2 + 12 * u(rng), 2 + 12 * u(rng), 2 + 15 * u(rng));
		const Eigen::Vector3d lo(ux(rng), uy(rng), 0);
		if (near_path(lo.head<2>(), size.head<2>())) continue;
		if (u(rng) < 0.3)
			addBox(w, rng, lo, {0.3, 0.3, 4 + 4 * u(rng)}, 40);  // a pole
		else
			addBox(w, rng, lo, size, 2);
		++placed;
	}
	return w;
}

/// The world's points within `range` of the sensor, in the sensor frame, with noise: a random half,
/// another one each call.
inline PointCloud scanFrom(const World& world, const Eigen::Isometry3d& world_T_sensor, std::mt19937& rng,
	double range = 80, double noise = 0.01)
{
	std::normal_distribution<double> n(0, noise);
	std::uniform_real_distribution<double> u(0, 1);
	const Eigen::Isometry3d sensor_T_world = world_T_sensor.inverse();
	PointCloud scan;
	for (const auto& p : world)
	{
		if (u(rng) < 0.5) continue;
		const Eigen::Vector3d q = sensor_T_world * p + Eigen::Vector3d(n(rng), n(rng), n(rng));
		if (q.head<2>().norm() > range) continue;
		scan.push_back(LidarPoint{float(q.x()), float(q.y()), float(q.z()), 0.f});
	}
	return scan;
}

/// The odometry of a true path: each step's translation scaled by `scale` and its yaw biased by
/// `yaw_bias_per_metre` [rad/m].
inline Trajectory driftingOdometry(const Trajectory& truth, double scale, double yaw_bias_per_metre)
{
	Trajectory odometry{truth.front()};
	for (std::size_t i = 1; i < truth.size(); ++i)
	{
		Eigen::Isometry3d step = truth[i - 1].pose.inverse() * truth[i].pose;
		const double length = step.translation().norm();
		step.translation() *= scale;
		step.linear() = Eigen::AngleAxisd(yaw_bias_per_metre * length, Eigen::Vector3d::UnitZ()) * step.linear();
		odometry.push_back({truth[i].t, odometry.back().pose * step});
	}
	return odometry;
}

/// RMS over the frame pairs (a, b) of the translation error of the relative pose b in a.
inline double revisitError(const Trajectory& truth, const Trajectory& estimate, const std::vector<std::pair<std::size_t, std::size_t>>& pairs)
{
	double sum = 0;
	for (const auto& [a, b] : pairs)
	{
		const Eigen::Isometry3d t = truth[a].pose.inverse() * truth[b].pose;
		const Eigen::Isometry3d e = estimate[a].pose.inverse() * estimate[b].pose;
		sum += (t.inverse() * e).translation().squaredNorm();
	}
	return std::sqrt(sum / static_cast<double>(pairs.size()));
}
}  // namespace vlo::loop::test
