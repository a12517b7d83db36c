#pragma once
// A synthetic street for the ICP tests: ground, two facades, a back wall and a few boxes, sampled at
// random points of their surfaces (in the world frame).
#include <vlo/core/frame.h>
#include <vlo/icp/voxel.h>

#include <Eigen/Geometry>
#include <random>

namespace vlo::icp::test
{
inline Points streetScene(std::size_t n, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	Points pts;
	pts.reserve(n);
	const auto rect = [&](const Eigen::Vector3d& o, const Eigen::Vector3d& a, const Eigen::Vector3d& b) -> Eigen::Vector3d {
		return o + u(rng) * a + u(rng) * b;
	};
	// Parked cars every 9 m on both sides (4.2 x 1.8 x 1.5 m boxes), and a kiosk: what fixes the motion
	// along the street, where ground and facades leave ICP sliding.
	const auto box = [&](const Eigen::Vector3d& lo, const Eigen::Vector3d& size) -> Eigen::Vector3d {
		const Eigen::Vector3d ex(size.x(), 0, 0), ey(0, size.y(), 0), ez(0, 0, size.z());
		switch (static_cast<int>(u(rng) * 5))
		{
			case 0: return rect(lo, ey, ez);
			case 1: return rect(lo + ex, ey, ez);
			case 2: return rect(lo, ex, ez);
			case 3: return rect(lo + ey, ex, ez);
			default: return rect(lo + ez, ex, ey);
		}
	};
	for (std::size_t i = 0; i < n; ++i)
	{
		switch (i % 8)
		{
			case 0:
			case 1:  // ground
				pts.push_back(rect({-40, -9, -1.8}, {80, 0, 0}, {0, 18, 0}));
				break;
			case 2: pts.push_back(rect({-40, 9, -1.8}, {80, 0, 0}, {0, 0, 10})); break;  // left facade
			case 3: pts.push_back(rect({-40, -9, -1.8}, {80, 0, 0}, {0, 0, 8})); break;  // right facade
			case 4: pts.push_back(rect({35, -9, -1.8}, {0, 18, 0}, {0, 0, 12})); break;  // back wall
			case 5:
			case 6:  // cars
			{
				const int k = static_cast<int>(u(rng) * 16);
				const double x = -36 + 9 * (k / 2) + 2.0 * (k % 2), y = k % 2 ? 4.5 : -6.5;
				pts.push_back(box({x, y, -1.8}, {4.2, 1.8, 1.5}));
				break;
			}
			default: pts.push_back(box({-12, -3, -1.8}, {2.5, 2.0, 3.0})); break;  // kiosk
		}
	}
	return pts;
}

/// The world points seen from a sensor at `world_T_sensor`, as a scan without times.
inline PointCloud scanFrom(const Points& world, const Eigen::Isometry3d& world_T_sensor)
{
	PointCloud scan;
	const Eigen::Isometry3d inv = world_T_sensor.inverse();
	for (const auto& p : world)
	{
		const Eigen::Vector3d q = inv * p;
		scan.push_back(LidarPoint{float(q.x()), float(q.y()), float(q.z()), 0.f});
	}
	return scan;
}

inline Eigen::Isometry3d motion(double x, double y, double z, double yaw_deg, double pitch_deg = 0, double roll_deg = 0)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = (Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()) *
		Eigen::AngleAxisd(pitch_deg * M_PI / 180, Eigen::Vector3d::UnitY()) *
		Eigen::AngleAxisd(roll_deg * M_PI / 180, Eigen::Vector3d::UnitX()))
					 .toRotationMatrix();
	T.translation() = Eigen::Vector3d(x, y, z);
	return T;
}

inline double rotationDeg(const Eigen::Isometry3d& T)
{
	return Eigen::AngleAxisd(T.linear()).angle() * 180 / M_PI;
}
}  // namespace vlo::icp::test
