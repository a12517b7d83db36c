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
/// A rectangle o + [0,1] a + [0,1] b of a world, seen at `density` returns per square metre.
struct Surface
{
	Eigen::Vector3d o, a, b;
	double density;
};
/// Each scan samples its own points of the surfaces, as a LiDAR's beams hit other spots each time.
using World = std::vector<Surface>;

inline Eigen::Isometry3d pose2d(double x, double y, double yaw)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	T.translation() = Eigen::Vector3d(x, y, 0);
	return T;
}

inline void addRectangle(World& w, const Eigen::Vector3d& o, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double density)
{
	w.push_back({o, a, b, density});
}

/// The four walls and the roof of a box on the ground.
inline void addBox(World& w, const Eigen::Vector3d& lo, const Eigen::Vector3d& size, double density)
{
	const Eigen::Vector3d ex(size.x(), 0, 0), ey(0, size.y(), 0), ez(0, 0, size.z());
	addRectangle(w, lo, ey, ez, density);
	addRectangle(w, lo + ex, ey, ez, density);
	addRectangle(w, lo, ex, ez, density);
	addRectangle(w, lo + ey, ex, ez, density);
	addRectangle(w, lo + ez, ex, ey, density);
}

inline void addGround(World& w, double x0, double x1, double y0, double y1, double density)
{
	addRectangle(w, {x0, y0, 0}, {x1 - x0, 0, 0}, {0, y1 - y0, 0}, density);
}

/// Ground, and boxes (buildings, cars) and poles at random, none where near_path(corner, size) says.
template <class NearPath>
World randomCity(unsigned seed, double x0, double x1, double y0, double y1, int objects, NearPath near_path)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1), u(0, 1);
	World w;
	addGround(w, x0, x1, y0, y1, 1);
	for (int placed = 0; placed < objects;)
	{
		const Eigen::Vector3d size(2 + 12 * u(rng), 2 + 12 * u(rng), 2 + 15 * u(rng));
		const Eigen::Vector3d lo(ux(rng), uy(rng), 0);
		if (near_path(lo.head<2>(), size.head<2>())) continue;
		if (u(rng) < 0.3)
			addBox(w, lo, {0.3, 0.3, 4 + 4 * u(rng)}, 40);  // a pole
		else
			addBox(w, lo, size, 4);
		++placed;
	}
	return w;
}

/// A street along x of identical buildings every `period` m on both sides, a pole in each gap, ground.
inline World facadeStreet(double x0, double x1, double period)
{
	World world;
	addGround(world, x0, x1, -20, 20, 1);
	for (double x = x0; x < x1; x += period)
	{
		addBox(world, {x, 8, 0}, {period - 2, 10, 12}, 4);
		addBox(world, {x, -18, 0}, {period - 2, 10, 12}, 4);
		addBox(world, {x + period - 1, 6, 0}, {0.3, 0.3, 6}, 40);
	}
	return world;
}

/// Points of the world's surfaces within `range` (horizontal) of the sensor, in the sensor frame, with
/// noise. The random numbers drawn do not depend on the pose, only which points are kept: one seed
/// seen from one place turned on the spot gives the same points.
inline PointCloud scanFrom(const World& world, const Eigen::Isometry3d& world_T_sensor, std::mt19937& rng,
	double range = 80, double noise = 0.01)
{
	std::normal_distribution<double> n(0, noise);
	std::uniform_real_distribution<double> u(0, 1);
	const Eigen::Isometry3d sensor_T_world = world_T_sensor.inverse();
	PointCloud scan;
	for (const auto& s : world)
	{
		const auto count = static_cast<int>(s.a.cross(s.b).norm() * s.density);
		for (int i = 0; i < count; ++i)
		{
			const double ua = u(rng), ub = u(rng), nx = n(rng), ny = n(rng), nz = n(rng);
			const Eigen::Vector3d q = sensor_T_world * (s.o + ua * s.a + ub * s.b) + Eigen::Vector3d(nx, ny, nz);
			if (q.head<2>().norm() > range) continue;
			scan.push_back(LidarPoint{float(q.x()), float(q.y()), float(q.z()), 0.f});
		}
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
