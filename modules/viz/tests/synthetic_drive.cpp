#include "synthetic.h"

#include <cmath>
#include <random>

namespace vlo::viz::synth
{
namespace
{
/// Curvature (1/m) at arc length s: gentle weaving plus a left and a right 90-degree turn.
double curvature(double s)
{
	auto turn = [](double s, double at, double angle) {
		const double sigma = 15;
		return angle / (sigma * std::sqrt(2 * M_PI)) * std::exp(-0.5 * std::pow((s - at) / sigma, 2));
	};
	return 0.004 * std::sin(2 * M_PI * s / 420) + turn(s, 330, M_PI / 2) + turn(s, 720, -M_PI / 2);
}
double height(double s) { return 4 * (1 - std::cos(2 * M_PI * s / 900)); }  // level at the start
}  // namespace

Trajectory curvedDrive(double length)
{
	Trajectory out;
	double s = 0, yaw = 0, x = 0, y = 0, t = 0;
	const double dt = 0.1;
	while (s <= length)
	{
		const double slope = (height(s + 0.5) - height(s - 0.5));
		StampedPose p;
		p.t = 1000 + t;
		p.pose.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
			Eigen::AngleAxisd(-std::atan(slope), Eigen::Vector3d::UnitY()))
							  .toRotationMatrix();
		p.pose.translation() = Eigen::Vector3d(x, y, height(s));
		out.push_back(p);
		const double v = 9.5 + 4.5 * std::sin(t / 17);  // 5..14 m/s
		for (int k = 0; k < 10; ++k)  // integrate the planar path in 10 sub-steps
		{
			const double ds = v * dt / 10;
			yaw += curvature(s) * ds;
			x += std::cos(yaw) * ds, y += std::sin(yaw) * ds, s += ds;
		}
		t += dt;
	}
	return relativeToFirst(out);
}

Trajectory driftingEstimate(const Trajectory& gt, double scaleDrift, double yawPerMetre, double noise, unsigned seed)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> n(0, 1);
	Trajectory out{gt.front()};
	const double total = pathLength(gt);
	double s = 0;
	for (size_t k = 1; k < gt.size(); ++k)
	{
		Eigen::Isometry3d d = gt[k - 1].pose.inverse() * gt[k].pose;
		const double step = d.translation().norm();
		s += step;
		d.translation() *= 1 + scaleDrift * s / total + 0.01 * noise * n(rng);
		d.translation() += noise * 0.02 * Eigen::Vector3d(n(rng), n(rng), n(rng));
		const double dyaw = yawPerMetre * step + 0.002 * noise * n(rng);
		d.linear() = Eigen::AngleAxisd(dyaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * d.linear();
		out.push_back({gt[k].t, out.back().pose * d});
	}
	return out;
}

PointCloud streetMap(const Trajectory& gt, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> u(0, 1);
	std::normal_distribution<double> n(0, 0.03);
	PointCloud map;
	auto add = [&](const Eigen::Isometry3d& T, double x, double y, double z) {
		const Eigen::Vector3d p = T * Eigen::Vector3d(x + n(rng), y + n(rng), z + n(rng));
		map.push_back({float(p.x()), float(p.y()), float(p.z()), float(u(rng))});
	};
	const double ground = -1.73;
	// Walk along the drive in 0.5 m steps; each side has its own sequence of lots (building or trees).
	double nextLot[2] = {0, 0}, lotHeight[2] = {10, 10}, lotOffset[2] = {11, 11};
	bool trees[2] = {false, false};
	double s = 0;
	for (size_t k = 1; k < gt.size(); ++k)
	{
		const double seg = (gt[k].pose.translation() - gt[k - 1].pose.translation()).norm();
		for (double a = 0; a < seg; a += 0.5, s += 0.5)
		{
			Eigen::Isometry3d T = gt[k - 1].pose;
			T.translation() += a / seg * (gt[k].pose.translation() - gt[k - 1].pose.translation());
			for (double y = -9; y <= 9; y += 0.6) add(T, u(rng) * 0.5, y, ground + 0.02 * std::sin(y));
			for (int side = 0; side < 2; ++side)
			{
				const double sign = side ? -1 : 1;
				if (s >= nextLot[side])  // new lot: 12-35 m long, 6-22 m high, sometimes trees
				{
					nextLot[side] = s + 12 + 23 * u(rng);
					lotHeight[side] = 6 + 16 * u(rng);
					lotOffset[side] = 10 + 3 * u(rng);
					trees[side] = u(rng) < 0.25;
				}
				const bool gap = nextLot[side] - s < 3;  // alleys between lots
				if (!trees[side] && !gap)
					for (double z = 0; z < lotHeight[side]; z += 0.6)
						add(T, u(rng) * 0.5, sign * lotOffset[side], ground + z);
				if (trees[side] && std::fmod(s, 9) < 0.5)
					for (int i = 0; i < 300; ++i)
					{
						const Eigen::Vector3d d =
							Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized() * (2.5 + 0.3 * n(rng));
						add(T, d.x(), sign * 8 + d.y(), ground + 5.5 + d.z());
						if (i < 20) add(T, 0, sign * 8, ground + 0.15 * i);
					}
				if (std::fmod(s + 7 * side, 31) < 4.5 && !trees[side])  // parked car: 4.5 x 1.8 x 1.5 m
					for (double z = 0; z < 1.5; z += 0.25)
						for (double y = 0; y < 1.8; y += 0.3) add(T, 0, sign * (5 + y), ground + z);
				if (std::fmod(s + 13 * side, 40) < 0.5)  // pole
					for (double z = 0; z < 7; z += 0.15) add(T, 0, sign * 7, ground + z);
			}
		}
	}
	return map;
}
}  // namespace vlo::viz::synth
