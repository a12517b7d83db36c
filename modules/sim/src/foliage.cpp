#include <vlo/sim/foliage.h>
#include <vlo/sim/rng.h>

#include <cmath>

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
