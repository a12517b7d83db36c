#include "synthetic_world.h"

#include <vlo/core/se3.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vlo::loam::test
{
namespace
{
double hitBox(const Box& b, const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_t)
{
	const double c = std::cos(b.yaw), s = std::sin(b.yaw);
	const Eigen::Vector3d lo = o - b.centre;
	const Eigen::Vector3d po(c * lo.x() + s * lo.y(), -s * lo.x() + c * lo.y(), lo.z());
	const Eigen::Vector3d pd(c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z());
	double t0 = 0, t1 = max_t;
	for (int a = 0; a < 3; ++a)
	{
		if (std::abs(pd[a]) < 1e-12)
		{
			if (std::abs(po[a]) > b.half[a]) return max_t;
			continue;
		}
		double ta = (-b.half[a] - po[a]) / pd[a], tb = (b.half[a] - po[a]) / pd[a];
		if (ta > tb) std::swap(ta, tb);
		t0 = std::max(t0, ta);
		t1 = std::min(t1, tb);
		if (t0 > t1) return max_t;
	}
	return t0 > 1e-9 ? t0 : max_t;  // rays starting inside a box see nothing of it
}

double hitCylinder(const Cylinder& cy, const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_t)
{
	const Eigen::Vector2d oc = o.head<2>() - cy.centre, dd = d.head<2>();
	const double a = dd.squaredNorm();
	if (a < 1e-12) return max_t;
	const double b = oc.dot(dd), c = oc.squaredNorm() - cy.radius * cy.radius;
	const double disc = b * b - a * c;
	if (disc < 0) return max_t;
	const double t = (-b - std::sqrt(disc)) / a;
	if (t <= 0 || t >= max_t) return max_t;
	const double z = o.z() + t * d.z();
	return (z >= cy.z0 && z <= cy.z1) ? t : max_t;
}
}  // namespace

double World::castSubset(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_t, const std::vector<int>& ids) const
{
	double t = max_t;
	if (ground && d.z() < -1e-9) t = std::min(t, -o.z() / d.z());
	const int nb = static_cast<int>(boxes.size());
	for (int id : ids) t = id < nb ? hitBox(boxes[id], o, d, t) : hitCylinder(cylinders[id - nb], o, d, t);
	return t;
}

double World::cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_t) const
{
	std::vector<int> all(numObjects());
	for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
	return castSubset(o, d, max_t, all);
}

LidarModel vlp16()
{
	LidarModel m;
	for (int k = 0; k < 16; ++k) m.elevations_deg.push_back(-15.0 + 2.0 * k);
	m.columns = 1800;
	m.max_range = 100;
	return m;
}

LidarModel hdl64()
{
	LidarModel m;
	for (int k = 0; k < 32; ++k) m.elevations_deg.push_back(2.0 - k / 3.0);
	for (int k = 0; k < 32; ++k) m.elevations_deg.push_back(-8.83 - 0.5 * k);
	m.columns = 2000;
	m.max_range = 120;
	return m;
}

PointCloud scan(const World& w, const LidarModel& m, const Eigen::Isometry3d& start, const Eigen::Isometry3d& end, std::mt19937* rng)
{
	// Objects binned by the azimuth interval they cover seen from the sweep's mid position, so
	// each column only tests the few objects in its direction.
	constexpr int kBins = 720;
	const Eigen::Vector3d mid = 0.5 * (start.translation() + end.translation());
	const double slack = (end.translation() - start.translation()).norm() + 0.5;
	std::vector<std::vector<int>> bins(kBins);
	const auto addBinned = [&](int id, const Eigen::Vector2d& c, double radius) {
		const Eigen::Vector2d v = c - mid.head<2>();
		const double dist = v.norm();
		if (dist - radius > m.max_range + slack) return;
		if (dist <= radius + slack)
		{
			for (auto& b : bins) b.push_back(id);
			return;
		}
		const double az = std::atan2(v.y(), v.x()), half = std::asin(std::min(1.0, (radius + slack) / dist));
		const int b0 = static_cast<int>(std::floor((az - half + M_PI) / (2 * M_PI) * kBins));
		const int b1 = static_cast<int>(std::floor((az + half + M_PI) / (2 * M_PI) * kBins));
		for (int b = b0; b <= b1; ++b) bins[((b % kBins) + kBins) % kBins].push_back(id);
	};
	const int nb = static_cast<int>(w.boxes.size());
	for (int i = 0; i < nb; ++i) addBinned(i, w.boxes[i].centre.head<2>(), w.boxes[i].half.head<2>().norm());
	for (std::size_t i = 0; i < w.cylinders.size(); ++i) addBinned(nb + static_cast<int>(i), w.cylinders[i].centre, w.cylinders[i].radius);

	std::normal_distribution<double> noise(0.0, m.noise_sigma);
	std::vector<Eigen::Vector3d> dirs;
	std::vector<std::uint16_t> ring;  // per beam: rank by elevation
	for (double e : m.elevations_deg)
	{
		dirs.emplace_back(std::cos(e * M_PI / 180), 0.0, std::sin(e * M_PI / 180));
		ring.push_back(static_cast<std::uint16_t>(
			std::count_if(m.elevations_deg.begin(), m.elevations_deg.end(), [e](double o) { return o < e; })));
	}
	PointCloud out;
	out.reserve(static_cast<std::size_t>(m.columns) * dirs.size());
	const float nan = std::numeric_limits<float>::quiet_NaN();
	for (int k = 0; k < m.columns; ++k)
	{
		const double az = M_PI - 2 * M_PI * k / m.columns;  // clockwise from behind
		const Eigen::Isometry3d T = interpolate(start, end, static_cast<double>(k) / m.columns);
		const double ca = std::cos(az), sa = std::sin(az);
		// The world direction of this column picks the bin (the sensor's yaw turns it).
		const Eigen::Vector3d wd = T.linear() * Eigen::Vector3d(ca, sa, 0);
		const int bin = std::clamp(static_cast<int>(std::floor((std::atan2(wd.y(), wd.x()) + M_PI) / (2 * M_PI) * kBins)), 0, kBins - 1);
		const float time = static_cast<float>(m.period * (static_cast<double>(k) / m.columns - 1.0));
		for (std::size_t j = 0; j < dirs.size(); ++j)
		{
			const Eigen::Vector3d& d0 = dirs[j];
			const Eigen::Vector3d dl(d0.x() * ca, d0.x() * sa, d0.z());
			double t = w.castSubset(T.translation(), T.linear() * dl, m.max_range, bins[bin]);
			if (t >= m.max_range)
			{
				if (m.nan_for_misses) out.push_back(LidarPoint{nan, nan, nan, 0});
				continue;
			}
			if (rng && m.noise_sigma > 0) t += noise(*rng);
			const Eigen::Vector3f p = (t * dl).cast<float>();
			out.push_back(LidarPoint{p.x(), p.y(), p.z(), 1.0f, time, ring[j]});
		}
	}
	return out;
}
}  // namespace vlo::loam::test
