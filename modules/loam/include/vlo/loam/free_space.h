#pragma once
// Free space seen by a scan: a map point that a beam of the current scan passes by, returning from
// well beyond it, is no longer there (a vehicle that has moved on leaves such ghosts in the map).
// The scan is binned by ring and azimuth; each bin keeps its nearest return, so only space that
// every return of the bin crossed counts as free.
#include <vlo/loam/rings.h>
#include <vlo/loam/slice_table.h>
#include <vlo/loam/types.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace vlo::loam
{
class FreeSpace
{
   public:
	/// `points`: the scan's returns in the sensor frame, with their rings; `n_azimuth_bins` per turn.
	FreeSpace(const ScanPoints& points, int n_azimuth_bins);
	FreeSpace(const ScanPoints& a, const ScanPoints& b, int n_azimuth_bins);

	/// True if a return's beam passes within `beam_radius` of q (sensor frame) and came back from
	/// more than margin + margin_per_metre * |q| beyond it. The range-proportional margin keeps the
	/// ground: a beam passing a ground point at grazing incidence meets the ground about
	/// |q| * beam_radius / sensor height farther on.
	bool seenThrough(const Eigen::Vector3f& q, float beam_radius, float margin, float margin_per_metre) const;

   private:
	void add(const ScanPoints& points);
	void finish();
	/// Inline: both run for every map point near the vehicle, every frame.
	int column(const Eigen::Vector3f& p) const
	{
		const float u = (fastAtan2(p.y(), p.x()) + static_cast<float>(M_PI)) / static_cast<float>(2 * M_PI);
		return std::min(n_cols_ - 1, std::max(0, static_cast<int>(u * static_cast<float>(n_cols_))));
	}
	/// atan2 of the height over the horizontal range: asin(z / r) without asin's cost.
	static float elevationOf(const Eigen::Vector3f& p) { return fastAtan2(p.z(), std::sqrt(p.x() * p.x() + p.y() * p.y())); }

	int n_cols_;
	std::vector<float> ring_elevation_;  ///< mean elevation of each ring's returns [rad]
	std::vector<int> ring_count_;
	std::vector<std::pair<float, std::size_t>> by_elevation_;  ///< (elevation, ring) of populated rings, ascending
	std::vector<Eigen::Vector4f> bins_;  ///< (unit direction, range) of the nearest return; range 0: none
	SliceTable elevations_;  ///< by_elevation_'s elevations (every map point near the vehicle looks its rings up)
};
}  // namespace vlo::loam
