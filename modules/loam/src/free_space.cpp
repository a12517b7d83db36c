#include <vlo/loam/free_space.h>

#include <algorithm>
#include <cmath>

namespace vlo::loam
{
FreeSpace::FreeSpace(const ScanPoints& points, int n_azimuth_bins) : n_cols_(n_azimuth_bins)
{
	add(points);
	finish();
}

FreeSpace::FreeSpace(const ScanPoints& a, const ScanPoints& b, int n_azimuth_bins) : n_cols_(n_azimuth_bins)
{
	add(a);
	add(b);
	finish();
}

void FreeSpace::add(const ScanPoints& points)
{
	// Sized once: grown ring by ring, the bins (a megabyte for 64 rings) would be copied each time.
	int top = -1;
	for (const ScanPoint& sp : points) top = std::max(top, sp.ring);
	const auto rings = static_cast<std::size_t>(top + 1);
	if (rings > ring_count_.size())
	{
		ring_count_.resize(rings, 0);
		ring_elevation_.resize(rings, 0.0f);
		bins_.resize(rings * static_cast<std::size_t>(n_cols_), Eigen::Vector4f::Zero());
	}
	for (const ScanPoint& sp : points)
	{
		const float r = sp.p.norm();
		if (sp.ring < 0 || r <= 0) continue;
		const std::size_t ring = static_cast<std::size_t>(sp.ring);
		ring_elevation_[ring] += elevationOf(sp.p);
		++ring_count_[ring];
		Eigen::Vector4f& b = bins_[ring * static_cast<std::size_t>(n_cols_) + static_cast<std::size_t>(column(sp.p))];
		if (b.w() == 0 || r < b.w()) b << sp.p / r, r;
	}
}

void FreeSpace::finish()
{
	for (std::size_t i = 0; i < ring_count_.size(); ++i)
		if (ring_count_[i] > 0)
		{
			ring_elevation_[i] /= static_cast<float>(ring_count_[i]);
			by_elevation_.emplace_back(ring_elevation_[i], i);
		}
	std::sort(by_elevation_.begin(), by_elevation_.end());
	std::vector<float> elevations;
	for (const auto& [e, ring] : by_elevation_) elevations.push_back(e);
	elevations_ = SliceTable(std::move(elevations));
}

bool FreeSpace::seenThrough(const Eigen::Vector3f& q, float beam_radius, float margin, float margin_per_metre) const
{
	const float r = q.norm();
	if (r <= beam_radius) return false;
	const float elevation = elevationOf(q), tolerance = beam_radius / r;
	const float beyond = r + margin + margin_per_metre * r;
	// The rings whose elevation is within the tolerance of q's (most points: none).
	auto it = by_elevation_.begin() + static_cast<std::ptrdiff_t>(elevations_.lowerBound(elevation - tolerance));
	if (it == by_elevation_.end() || it->first > elevation + tolerance) return false;
	const std::size_t col = static_cast<std::size_t>(column(q));
	for (; it != by_elevation_.end() && it->first <= elevation + tolerance; ++it)
	{
		const std::size_t ring = it->second;
		const Eigen::Vector4f& b = bins_[ring * static_cast<std::size_t>(n_cols_) + col];
		if (b.w() <= beyond) continue;
		const Eigen::Vector3f d = b.head<3>();
		if ((q - d * d.dot(q)).norm() < beam_radius) return true;
	}
	return false;
}
}  // namespace vlo::loam
