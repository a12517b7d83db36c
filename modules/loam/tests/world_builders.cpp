// Paths and worlds for the synthetic drives.
#include "synthetic_world.h"

#include <cmath>

namespace vlo::loam::test
{
void Path::add(double length, double curvature)
{
	Seg s{length, curvature, total_, 0, 0, 0};
	if (!segs_.empty())
	{
		const Eigen::Isometry3d e = at(total_);
		s.x0 = e.translation().x();
		s.y0 = e.translation().y();
		s.yaw0 = std::atan2(e.linear()(1, 0), e.linear()(0, 0));
	}
	segs_.push_back(s);
	total_ += length;
}

Eigen::Isometry3d Path::at(double s) const
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	if (segs_.empty()) return T;
	std::size_t i = 0;
	while (i + 1 < segs_.size() && s > segs_[i].s0 + segs_[i].length) ++i;
	const Seg& g = segs_[i];
	const double u = s - g.s0;
	double x, y, yaw = g.yaw0 + g.curvature * u;
	if (std::abs(g.curvature) < 1e-9)
	{
		x = g.x0 + u * std::cos(g.yaw0);
		y = g.y0 + u * std::sin(g.yaw0);
	}
	else
	{
		x = g.x0 + (std::sin(yaw) - std::sin(g.yaw0)) / g.curvature;
		y = g.y0 - (std::cos(yaw) - std::cos(g.yaw0)) / g.curvature;
	}
	T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	T.translation() = Eigen::Vector3d(x, y, 0);
	return T;
}

Eigen::Isometry3d lidarPoseAt(const Path& path, double s)
{
	Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
	body.linear() = (Eigen::AngleAxisd(0.01 * std::sin(s * 0.21), Eigen::Vector3d::UnitX()) *
		Eigen::AngleAxisd(0.012 * std::sin(s * 0.13 + 1.0), Eigen::Vector3d::UnitY()))
						.toRotationMatrix();
	body.translation() = Eigen::Vector3d(0, 0, 1.73 + 0.02 * std::sin(s * 0.37));
	return path.at(s) * body;
}

World urbanWorld(const Path& path, unsigned seed)
{
	World w;
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> U(0.0, 1.0);
	const auto place = [&](double s, double offset, const Eigen::Vector3d& half, double z, double yaw_jitter) {
		const Eigen::Isometry3d P = path.at(s);
		const Eigen::Vector3d side = P.linear().col(1);
		const double yaw = std::atan2(P.linear()(1, 0), P.linear()(0, 0)) + yaw_jitter;
		w.boxes.push_back(Box{P.translation() + offset * side + Eigen::Vector3d(0, 0, z), half, yaw});
	};
	for (int sign : {-1, 1})
	{
		// Buildings: blocks of 8-25 m along the street with 0-6 m gaps, set back 9-14 m.
		for (double s = -30; s < path.length() + 30;)
		{
			const double len = 8 + 17 * U(rng), depth = 8 + 7 * U(rng), height = 6 + 14 * U(rng);
			const double setback = 9 + 5 * U(rng);
			place(s + len / 2, sign * (setback + depth / 2), Eigen::Vector3d(len / 2, depth / 2, height / 2), height / 2,
				0.15 * (U(rng) - 0.5));
			s += len + 6 * U(rng);
		}
		// Poles and trunks on the pavement, parked cars at the kerb.
		for (double s = 5 * U(rng); s < path.length() + 30; s += 12 + 10 * U(rng))
		{
			const Eigen::Isometry3d P = path.at(s);
			const Eigen::Vector2d c = (P.translation() + sign * (6.5 + U(rng)) * P.linear().col(1)).head<2>();
			w.cylinders.push_back(Cylinder{c, 0.1 + 0.25 * U(rng), 0.0, 3 + 5 * U(rng)});
		}
		for (double s = 10 * U(rng); s < path.length() + 30; s += 8 + 20 * U(rng))
			place(s, sign * (4.5 + 0.5 * U(rng)), Eigen::Vector3d(2.2, 0.9, 0.75), 0.75, 0.1 * (U(rng) - 0.5));
	}
	return w;
}

World corridorWorld(double length, double half_width, double height)
{
	World w;
	for (int sign : {-1, 1})
		w.boxes.push_back(Box{Eigen::Vector3d(0, sign * (half_width + 0.5), height / 2),
			Eigen::Vector3d(length / 2, 0.5, height / 2), 0.0});
	return w;
}
}  // namespace vlo::loam::test
