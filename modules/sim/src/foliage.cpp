#include <vlo/sim/foliage.h>
#include <vlo/sim/rng.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vlo::sim
{
namespace
{
constexpr double kCell = 8.0;  // m
constexpr double kHullSlack = 0.05;  // flat faces and the bumps' interpolation: relative radius

/// Far intersection of the ray p + t d with the ellipsoid (centre, radii), t > 0; 0 if none.
double exitDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& d, const Eigen::Vector3d& centre,
	const Eigen::Vector3d& radii)
{
	const Eigen::Vector3d q = (p - centre).cwiseQuotient(radii), e = d.cwiseQuotient(radii);
	const double a = e.squaredNorm(), b = q.dot(e), c = q.squaredNorm() - 1;
	const double disc = b * b - a * c;
	if (disc <= 0) return 0;
	return std::max(0.0, (-b + std::sqrt(disc)) / a);
}
}  // namespace

void Foliage::add(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii, double roughness)
{
	const int id = static_cast<int>(crowns_.size());
	crowns_.push_back({centre, radii, roughness});
	const double reach = radii.head<2>().maxCoeff() * (1 + roughness + kHullSlack);
	const auto lo = ((centre.head<2>().array() - reach) / kCell).floor().cast<int64_t>();
	const auto hi = ((centre.head<2>().array() + reach) / kCell).floor().cast<int64_t>();
	for (int64_t i = lo.x(); i <= hi.x(); ++i)
		for (int64_t j = lo.y(); j <= hi.y(); ++j) cells_[cellKey(i, j)].push_back(id);
}

const Foliage::Crown* Foliage::crownAt(const Eigen::Vector3d& p) const
{
	const auto it = cells_.find(cellKey(static_cast<int64_t>(std::floor(p.x() / kCell)), static_cast<int64_t>(std::floor(p.y() / kCell))));
	if (it == cells_.end()) return nullptr;
	for (int id : it->second)
	{
		const Crown& c = crowns_[static_cast<std::size_t>(id)];
		const double rho = (p - c.centre).cwiseQuotient(c.radii).norm();
		if (std::abs(rho - 1) <= c.roughness + kHullSlack) return &c;
	}
	return nullptr;
}

bool Foliage::penetrate(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double mean_depth, Rng& rng, double& range) const
{
	if (mean_depth <= 0) return true;
	const Eigen::Vector3d hit = o + range * d;
	const Crown* c = crownAt(hit);
	if (!c) return true;
	// Beyond the hull's outermost bumps the beam has left the crown.
	const double inside = exitDistance(hit, d, c->centre, c->radii * (1 + c->roughness));
	const double depth = -mean_depth * std::log(1 - rng.uniform());
	if (depth >= inside) return false;
	range += depth;
	return true;
}
}  // namespace vlo::sim

namespace vlo::sim
{
namespace
{
/// A smooth value noise in [0, 1] with features ~0.4 m apart: hashed lattice values, trilinear blend.
double leafNoise(const Eigen::Vector3d& p)
{
	const Eigen::Vector3d q = p / 0.4;
	const Eigen::Vector3d f = q.array().floor();
	const auto hash = [](int64_t x, int64_t y, int64_t z) {
		uint64_t h = static_cast<uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<uint64_t>(y) * 0xC2B2AE3D27D4EB4FULL ^
			static_cast<uint64_t>(z) * 0x165667B19E3779F9ULL;
		h ^= h >> 29, h *= 0xBF58476D1CE4E5B9ULL, h ^= h >> 32;
		return static_cast<double>(h >> 11) / 9007199254740992.0;
	};
	const Eigen::Vector3d w = q - f;
	const Eigen::Vector3d s = w.array() * w.array() * (3 - 2 * w.array());
	const auto i = f.cast<int64_t>();
	double v = 0;
	for (int c = 0; c < 8; ++c)
	{
		const int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
		const double weight = (dx ? s.x() : 1 - s.x()) * (dy ? s.y() : 1 - s.y()) * (dz ? s.z() : 1 - s.z());
		v += weight * hash(i.x() + dx, i.y() + dy, i.z() + dz);
	}
	return v;
}

/// Entry and exit of the ray p + t d in the ellipsoid, t >= 0; false if it misses.
bool chord(const Eigen::Vector3d& p, const Eigen::Vector3d& d, const Eigen::Vector3d& centre, const Eigen::Vector3d& radii,
	double& t0, double& t1)
{
	const Eigen::Vector3d q = (p - centre).cwiseQuotient(radii), e = d.cwiseQuotient(radii);
	const double a = e.squaredNorm(), b = q.dot(e), c = q.squaredNorm() - 1;
	const double disc = b * b - a * c;
	if (disc <= 0) return false;
	t0 = std::max(0.0, (-b - std::sqrt(disc)) / a), t1 = (-b + std::sqrt(disc)) / a;
	return t1 > t0;
}
}  // namespace

bool Foliage::shades(const Eigen::Vector3d& p, const Eigen::Vector3d& to_sun, double gap_fraction) const
{
	constexpr double kTop = 16;  // m: no crown reaches higher above the ground here
	const double horizontal = to_sun.head<2>().norm();
	const double reach = horizontal > 1e-9 ? std::min(40.0, std::max(0.0, kTop - p.z()) / to_sun.z() * horizontal) : 0;
	const Eigen::Vector2d step = horizontal > 1e-9 ? Eigen::Vector2d(to_sun.head<2>() / horizontal) : Eigen::Vector2d::Zero();
	std::vector<int> seen;
	for (double h = 0;; h += kCell / 2)
	{
		const Eigen::Vector2d xy = p.head<2>() + std::min(h, reach) * step;
		const auto it = cells_.find(cellKey(static_cast<int64_t>(std::floor(xy.x() / kCell)), static_cast<int64_t>(std::floor(xy.y() / kCell))));
		if (it != cells_.end())
			for (int id : it->second)
			{
				if (std::find(seen.begin(), seen.end(), id) != seen.end()) continue;
				seen.push_back(id);
				const Crown& c = crowns_[static_cast<std::size_t>(id)];
				double t0 = 0, t1 = 0;
				if (!chord(p, to_sun, c.centre, c.radii * (1 + 0.5 * c.roughness), t0, t1)) continue;
				t0 = std::max(t0, 0.05);  // a point on this crown's own hull: not shaded by its own surface
				if (t1 - t0 > 0.2 && leafNoise(p + t0 * to_sun) >= gap_fraction) return true;
			}
		if (h >= reach) break;
	}
	return false;
}
}  // namespace vlo::sim
