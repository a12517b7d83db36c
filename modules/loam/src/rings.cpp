#include <vlo/loam/rings.h>

#include <vlo/core/sweep_times.h>
#include <vlo/core/units.h>

#include <algorithm>
#include <cmath>

namespace vlo::loam
{
namespace
{
constexpr float kMaxSecondsAway = 1.0f;  ///< a point time farther from the frame's is invalid (sweeps last 0.05-0.2 s)

// Rings of a scan that carries the sensor's ids: the highest id below kMaxRings + 1, at least the
// ring model's count (ids are ordered by elevation, 0 = lowest, as the readers deliver them).
int ringsInData(const PointCloud& scan, int model_rings)
{
	int n = model_rings;
	for (const LidarPoint& p : scan)
		if (p.ring < kMaxRings) n = std::max(n, p.ring + 1);
	return n;
}
}  // namespace

std::vector<double> RingModel::hdl64Elevations()
{
	std::vector<double> e;
	for (int k = 0; k < 32; ++k) e.push_back(2.0 - k / 3.0);
	for (int k = 0; k < 32; ++k) e.push_back(-8.83 - 0.5 * k);
	return e;
}

RingModel::RingModel(const ScanOptions& o)
{
	o.validate();
	if (o.ring_model == "hdl64") elevations_deg_ = hdl64Elevations();
	else if (o.ring_model == "table") elevations_deg_ = o.elevation_table_deg;
	else
		for (int k = 0; k < o.n_rings; ++k)
			elevations_deg_.push_back(o.vfov_min_deg + (o.vfov_max_deg - o.vfov_min_deg) * k / (o.n_rings - 1));
	std::sort(elevations_deg_.begin(), elevations_deg_.end());
	elevations_deg_.erase(std::unique(elevations_deg_.begin(), elevations_deg_.end()), elevations_deg_.end());

	std::vector<float> tan_bounds;  // tan of the midpoints between consecutive beams
	for (std::size_t k = 0; k + 1 < elevations_deg_.size(); ++k)
		tan_bounds.push_back(static_cast<float>(std::tan(0.5 * (elevations_deg_[k] + elevations_deg_[k + 1]) * kRadPerDeg)));
	tan_bounds_ = SliceTable(std::move(tan_bounds));
	const double lo = std::max(-89.9, elevations_deg_.front() - o.fov_margin_deg);
	const double hi = std::min(89.9, elevations_deg_.back() + o.fov_margin_deg);
	tan_lo_ = static_cast<float>(std::tan(lo * kRadPerDeg));
	tan_hi_ = static_cast<float>(std::tan(hi * kRadPerDeg));
}

int RingModel::ringOf(float z, float rho) const
{
	const float t = z / rho;
	if (!(t >= tan_lo_ && t <= tan_hi_)) return -1;  // also rejects NaN (rho = z = 0)
	return static_cast<int>(tan_bounds_.upperBound(t));
}

int RingModel::nearestRing(float z, float rho) const
{
	const float t = z / rho;
	if (std::isnan(t)) return -1;
	return static_cast<int>(tan_bounds_.upperBound(t));
}

int RingScan::populatedRings(std::size_t min_points) const
{
	int n = 0;
	for (int r = 0; r < numRings(); ++r) n += ringSize(r) >= min_points ? 1 : 0;
	return n;
}

ScanPreprocessor::ScanPreprocessor(const ScanOptions& o) : opt_(o), model_(o) {}

RingScan ScanPreprocessor::process(const PointCloud& scan)
{
	RingScan out;
	out.rings_from_data = scan.has_ring;
	// A scan whose points all share one time (motion-compensated, or an exact sensor: every time 0)
	// has nothing to deskew: its rings are ordered by azimuth as without times.
	out.times_from_data = hasTimeSpread(scan);
	const int n_rings = out.rings_from_data ? ringsInData(scan, model_.numRings()) : model_.numRings();
	out.n_input = scan.size();
	out.ring_begin.assign(n_rings + 1, 0);
	count_.assign(n_rings, 0);
	ring_of_.resize(scan.size());

	const float min2 = static_cast<float>(opt_.min_range * opt_.min_range);
	const float max2 = static_cast<float>(opt_.max_range * opt_.max_range);
	// Two passes, no intermediate copy: the first keeps the ring of each usable point (-1: dropped)
	// and counts the rings, the second writes each point straight to its place (a stable counting
	// sort by ring, which keeps the sensor's order within a ring).
	for (std::size_t i = 0; i < scan.size(); ++i)
	{
		const LidarPoint& lp = scan[i];
		ring_of_[i] = -1;
		if (!std::isfinite(lp.x) || !std::isfinite(lp.y) || !std::isfinite(lp.z))
		{
			++out.n_invalid;
			continue;
		}
		const float rho2 = lp.x * lp.x + lp.y * lp.y, r2 = rho2 + lp.z * lp.z;
		if (r2 < min2 || r2 > max2)
		{
			++out.n_out_of_range;
			continue;
		}
		const int ring = !out.rings_from_data ? model_.ringOf(lp.z, std::sqrt(rho2)) : lp.ring < n_rings ? lp.ring
																										 : -1;
		if (ring < 0)
		{
			++out.n_out_of_fov;
			continue;
		}
		if (out.times_from_data && !(std::fabs(lp.time) <= kMaxSecondsAway))  // NaN too: not a time of this sweep
		{
			++out.n_invalid;
			continue;
		}
		ring_of_[i] = static_cast<std::int16_t>(ring);
		++count_[ring];
	}
	for (int r = 0; r < n_rings; ++r) out.ring_begin[r + 1] = out.ring_begin[r] + count_[r];
	out.points.resize(out.ring_begin.back());
	std::vector<std::size_t> next(out.ring_begin.begin(), out.ring_begin.end() - 1);

	const SpinningSweep ordering;  // without the sensor's times: a Velodyne's turn, only to order each ring
	for (std::size_t i = 0; i < scan.size(); ++i)
	{
		const int ring = ring_of_[i];
		if (ring < 0) continue;
		const LidarPoint& lp = scan[i];
		ScanPoint& p = out.points[next[ring]++];
		p.p = Eigen::Vector3f(lp.x, lp.y, lp.z);
		p.ring = ring;
		p.time = out.times_from_data ? lp.time : static_cast<float>(ordering.timeAt(fastAtan2(lp.y, lp.x)));
	}

	// Most sensors deliver rings in time order, or rotated by the ring's start offset when the
	// order is ring by ring (KITTI): rotate in that case and sort only otherwise.
	const auto by_time = [](const ScanPoint& a, const ScanPoint& b) { return a.time < b.time; };
	for (int r = 0; r < n_rings; ++r)
	{
		auto b = out.points.begin() + out.ring_begin[r], e = out.points.begin() + out.ring_begin[r + 1];
		auto d = std::is_sorted_until(b, e, by_time);
		if (d == e) continue;
		if (std::is_sorted(d, e, by_time) && !by_time(*b, *(e - 1))) std::rotate(b, d, e);
		else std::sort(b, e, by_time);
	}
	return out;
}
}  // namespace vlo::loam
