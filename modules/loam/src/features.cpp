#include <vlo/loam/features.h>

#include <vlo/loam/rings.h>
#include <vlo/core/voxel_hash_map.h>

#include <algorithm>
#include <cmath>

namespace vlo::loam
{
void RingVoxelMerger::add(const ScanPoint& p)
{
	const Eigen::Vector3i key = cellOf(p.p, inv_leaf_);
	if (count_ > 0 && key != key_) flush();
	if (count_ == 0)
	{
		key_ = key;
		ring_ = p.ring;
	}
	sum_ += p.p;
	time_sum_ += p.time;
	++count_;
}

void RingVoxelMerger::flush()
{
	if (count_ == 0) return;
	ScanPoint q;
	q.p = sum_ / static_cast<float>(count_);
	q.time = time_sum_ / static_cast<float>(count_);
	q.ring = ring_;
	out_.push_back(q);
	sum_.setZero();
	time_sum_ = 0;
	count_ = 0;
}

FeatureExtractor::FeatureExtractor(const FeatureOptions& o) : opt_(o) {}

FeatureSet FeatureExtractor::extract(const RingScan& scan)
{
	FeatureSet out;
	out.n_rings = scan.numRings();
	out.rings_from_data = scan.rings_from_data;
	for (int r = 0; r < scan.numRings(); ++r)
		extractRing(scan.points.data() + scan.ring_begin[r], static_cast<int>(scan.ringSize(r)), out);
	return out;
}

// LOAM's rejection of points whose neighbourhood is not a reliable surface sample (Fig. 4 of the
// paper): (a) the far side of a depth jump between beams pointing almost the same way, which may
// become occluded after a small motion; (b) points where the beam grazes the surface, whose
// spacing to both neighbours is large relative to the range.
void FeatureExtractor::markUnreliable(const ScanPoint* p, int n)
{
	const int W = opt_.curvature_half_window;
	if (opt_.reject_occluded)
		for (int i = W; i < n - W - 1; ++i)
		{
			const Eigen::Vector3f& a = p[i].p;
			const Eigen::Vector3f& b = p[i + 1].p;
			if ((b - a).squaredNorm() <= opt_.occlusion_gap_sq) continue;
			const float ra = a.norm(), rb = b.norm();
			if (ra > rb)
			{
				if ((a * (rb / ra) - b).norm() / rb < opt_.occlusion_angle)
					std::fill(picked_.begin() + (i - W), picked_.begin() + i + 1, kUnreliable);
			}
			else if ((b * (ra / rb) - a).norm() / ra < opt_.occlusion_angle)
				std::fill(picked_.begin() + i + 1, picked_.begin() + std::min(n, i + W + 2), kUnreliable);
		}
	if (opt_.reject_parallel)
		for (int i = W; i < n - W; ++i)
		{
			const float lim = static_cast<float>(opt_.parallel_ratio) * p[i].p.squaredNorm();
			if ((p[i].p - p[i - 1].p).squaredNorm() > lim && (p[i + 1].p - p[i].p).squaredNorm() > lim)
				picked_[i] = kUnreliable;
		}
}

// Missing returns (sky, glass, out of range, or something that blocks the beam and returns nothing)
// leave gaps in azimuth along a ring. A curvature window across a gap sums points far apart, so
// both borders look like edges (and smooth planes may look bent) that move with whatever hides the
// world: the border points are no surface sample. Gaps are counted in the ring's median azimuth step.
void FeatureExtractor::markAzimuthGaps(const ScanPoint* p, int n)
{
	step_.resize(n - 1);
	float az = fastAtan2(p[0].p.y(), p[0].p.x());
	for (int i = 0; i + 1 < n; ++i)
	{
		const float next = fastAtan2(p[i + 1].p.y(), p[i + 1].p.x()), d = std::fabs(next - az);
		step_[i] = std::min(d, 6.28318531f - d);
		az = next;
	}
	sorted_step_ = step_;
	const auto mid = sorted_step_.begin() + sorted_step_.size() / 2;
	std::nth_element(sorted_step_.begin(), mid, sorted_step_.end());
	const float max_step = static_cast<float>(opt_.max_azimuth_gap) * *mid;
	const int W = opt_.curvature_half_window;
	// The window of point i holds the steps i - W .. i + W - 1.
	for (int j = 0; j + 1 < n; ++j)
		if (step_[j] > max_step)
			std::fill(picked_.begin() + std::max(0, j - W + 1), picked_.begin() + std::min(n, j + W + 1), kUnreliable);
}

// Picked features keep their neighbours from being picked, so features spread over the scan,
// but not across a gap: the other side of a gap is a different surface.
void FeatureExtractor::suppressNeighbours(const ScanPoint* p, int n, int i)
{
	picked_[i] = std::max<std::uint8_t>(picked_[i], kSuppressed);
	const float gap = static_cast<float>(opt_.suppress_gap_sq);
	for (int l = 1; l <= opt_.curvature_half_window && i + l < n; ++l)
	{
		if ((p[i + l].p - p[i + l - 1].p).squaredNorm() > gap) break;
		picked_[i + l] = std::max<std::uint8_t>(picked_[i + l], kSuppressed);
	}
	for (int l = 1; l <= opt_.curvature_half_window && i - l >= 0; ++l)
	{
		if ((p[i - l].p - p[i - l + 1].p).squaredNorm() > gap) break;
		picked_[i - l] = std::max<std::uint8_t>(picked_[i - l], kSuppressed);
	}
}

// Every point within the window of an edge has a high curvature; where samples are farther apart
// than the suppression gap (far or oblique surfaces) LOAM would then pick several points along the
// surface next to the edge, so only the peak of the curvature counts.
bool FeatureExtractor::isLocalMax(int i, int n) const
{
	const int W = opt_.curvature_half_window;
	for (int j = std::max(W, i - W); j <= std::min(n - W - 1, i + W); ++j)
		if (curv_[j] > curv_[i]) return false;
	return true;
}

// An object's outline against a farther background (a silhouette) is where the beam leaves the
// object's body: on a rounded body (a car, a pole, a trunk) that place moves round it as the sensor
// moves, so it is no fixed 3D line. A crease (a corner, both sides seen) has no such jump.
bool FeatureExtractor::onSilhouette(const ScanPoint* p, int n, int i) const
{
	const int W = opt_.curvature_half_window;
	const float gap = static_cast<float>(opt_.occlusion_gap_sq);
	for (int j = std::max(0, i - W - 1); j < std::min(n - 1, i + W + 1); ++j)
	{
		if ((p[j + 1].p - p[j].p).squaredNorm() <= gap) continue;
		// The side of the jump that i is on must be the nearer one.
		const bool i_after = j + 1 <= i;
		const float near_sq = (i_after ? p[j + 1] : p[j]).p.squaredNorm();
		const float far_sq = (i_after ? p[j] : p[j + 1]).p.squaredNorm();
		if (near_sq < far_sq) return true;
	}
	return false;
}

void FeatureExtractor::extractRing(const ScanPoint* p, int n, FeatureSet& out)
{
	const int W = opt_.curvature_half_window;
	curv_.assign(std::max(n, 0), 0.0f);
	if (n < 2 * W + 2 * opt_.n_sectors) return;
	picked_.assign(n, 0);
	label_.assign(n, 0);
	for (int a = 0; a < 3; ++a) coord_[a].resize(n), diff_[a].resize(n);

	// Per coordinate and one offset at a time, so that the loops over the points vectorise: the
	// sums are those of sum_j (p[i-j] + p[i+j]) - 2W p[i], added in the same order per point.
	for (int a = 0; a < 3; ++a)
	{
		float* x = coord_[a].data();
		float* d = diff_[a].data();
		for (int i = 0; i < n; ++i) x[i] = p[i].p[a];
		for (int i = W; i < n - W; ++i) d[i] = static_cast<float>(-2 * W) * x[i];
		for (int j = 1; j <= W; ++j)
			for (int i = W; i < n - W; ++i) d[i] += x[i - j] + x[i + j];
	}
	for (int i = W; i < n - W; ++i) curv_[i] = diff_[0][i] * diff_[0][i] + diff_[1][i] * diff_[1][i] + diff_[2][i] * diff_[2][i];
	markUnreliable(p, n);
	if (opt_.max_azimuth_gap > 0) markAzimuthGaps(p, n);

	const float sharp_thr = static_cast<float>(opt_.sharp_threshold);
	const float flat_thr = static_cast<float>(opt_.flat_threshold);
	RingVoxelMerger less_flat(static_cast<float>(opt_.less_flat_leaf), out.less_flat);
	const int span = n - 2 * W;
	for (int k = 0; k < opt_.n_sectors; ++k)
	{
		const int sp = W + span * k / opt_.n_sectors, ep = W + span * (k + 1) / opt_.n_sectors;
		// Only candidates are ordered, and only as far as needed: most points are neither sharp
		// nor among the few flattest (a full sort of every sector costs milliseconds).
		order_.clear();
		for (int i = sp; i < ep; ++i)
			if (curv_[i] > sharp_thr && !picked_[i] && (!opt_.sharp_local_max || isLocalMax(i, n)))
				order_.emplace_back(-curv_[i], i);
		std::sort(order_.begin(), order_.end());
		int n_sharp = 0;
		for (const auto& [c, i] : order_)
		{
			if (picked_[i]) continue;
			if (++n_sharp > opt_.max_less_sharp) break;
			label_[i] = n_sharp <= opt_.max_sharp ? 2 : 1;
			if (label_[i] == 2) out.sharp.push_back(p[i]);
			out.less_sharp.push_back(p[i]);
			out.less_sharp_silhouette.push_back(onSilhouette(p, n, i) ? 1 : 0);
			suppressNeighbours(p, n, i);
		}

		order_.clear();
		for (int i = sp; i < ep; ++i)
			if (curv_[i] < flat_thr && !picked_[i]) order_.emplace_back(curv_[i], i);
		// Suppression skips a few candidates per pick: the first 8 * max_flat nearly always suffice.
		const std::size_t head = std::min(order_.size(), static_cast<std::size_t>(8 * opt_.max_flat + 8));
		std::nth_element(order_.begin(), order_.begin() + head - (head ? 1 : 0), order_.end());
		std::sort(order_.begin(), order_.begin() + head);
		int n_flat = 0;
		for (std::size_t o = 0; o < order_.size() && n_flat < opt_.max_flat; ++o)
		{
			if (o == head) std::sort(order_.begin() + head, order_.end());
			const int i = order_[o].second;
			if (picked_[i]) continue;
			label_[i] = -1;
			out.flat.push_back(p[i]);
			++n_flat;
			suppressNeighbours(p, n, i);
		}
		// Plane samples for the next scan and the map: smooth and reliable points only (A-LOAM takes
		// every non-edge point, but points next to corners fit wrong planes on sparse sensors).
		const float less_flat_thr = static_cast<float>(opt_.less_flat_threshold);
		for (int i = sp; i < ep; ++i)
			if (label_[i] <= 0 && picked_[i] != kUnreliable && curv_[i] < less_flat_thr) less_flat.add(p[i]);
	}
}
}  // namespace vlo::loam
