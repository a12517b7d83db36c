#include <vlo/loam/ring_search.h>

#include <vlo/loam/rings.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vlo::loam
{
namespace
{
constexpr float kPi = 3.14159265f;
constexpr float kAtanError = 1e-4f;  // more than fastAtan2's, twice
}  // namespace

RingSearch::Query::Query(const Eigen::Vector3f& q)
	: p(q), az(fastAtan2(q.y(), q.x())), elevation(fastAtan2(q.z(), std::sqrt(q.x() * q.x() + q.y() * q.y()))), range(q.norm())
{
}

// A ring comes in time order: its azimuths rise (or fall, clockwise) from where the sweep started.
// Rotated (and reversed) to start at the smallest, a strictly rising ring is what a sort would give;
// anything else (ties, unordered input) is sorted.
void RingSearch::sortByAzimuth(Entry* b, int n)
{
	const auto less = [](const Entry& x, const Entry& y) { return x.az < y.az; };
	const auto strictly_rising = [&] {
		for (int k = 1; k < n; ++k)
			if (!less(b[k - 1], b[k])) return false;
		return true;
	};
	if (n < 2) return;
	const auto rotate_to_min = [&] { std::rotate(b, std::min_element(b, b + n, less), b + n); };
	rotate_to_min();
	if (strictly_rising()) return;
	std::reverse(b, b + n);
	rotate_to_min();
	if (strictly_rising()) return;
	std::sort(b, b + n, less);
}

void RingSearch::build(const ScanPoints& points, int n_rings)
{
	points_ = &points;
	n_rings_ = n_rings;
	begin_.assign(n_rings + 1, 0);
	for (const ScanPoint& p : points)
		if (p.ring >= 0 && p.ring < n_rings) ++begin_[p.ring + 1];
	for (int r = 0; r < n_rings; ++r) begin_[r + 1] += begin_[r];
	entries_.resize(begin_.back());
	std::vector<std::size_t> next(begin_.begin(), begin_.end() - 1);
	const float inf = std::numeric_limits<float>::infinity();
	std::vector<float> slope_lo(n_rings, inf), slope_hi(n_rings, -inf);
	for (std::size_t i = 0; i < points.size(); ++i)
	{
		const ScanPoint& p = points[i];
		if (p.ring < 0 || p.ring >= n_rings) continue;
		const float rho = std::hypot(p.p.x(), p.p.y());
		const float inv = rho > 0 ? 1.0f / rho : 0.0f;
		if (rho > 0)
		{
			const float slope = p.p.z() * inv;
			slope_lo[p.ring] = std::min(slope_lo[p.ring], slope);
			slope_hi[p.ring] = std::max(slope_hi[p.ring], slope);
		}
		entries_[next[p.ring]++] =
			Entry{fastAtan2(p.p.y(), p.p.x()), p.p.x() * inv, p.p.y() * inv, p.p.x(), p.p.y(), p.p.z(), static_cast<int>(i)};
	}
	// A ring without a point off the axis keeps the widest span: always searched.
	elevation_lo_.assign(n_rings, -kPi);
	elevation_hi_.assign(n_rings, kPi);
	for (int r = 0; r < n_rings; ++r)
		if (slope_lo[r] <= slope_hi[r])
			elevation_lo_[r] = fastAtan2(slope_lo[r], 1.0f), elevation_hi_[r] = fastAtan2(slope_hi[r], 1.0f);
	bin_start_.assign(static_cast<std::size_t>(n_rings) * (kBins + 1), 0);
	for (int r = 0; r < n_rings; ++r)
	{
		Entry* b = entries_.data() + begin_[r];
		const int n = static_cast<int>(begin_[r + 1] - begin_[r]);
		sortByAzimuth(b, n);
		int* bins = bin_start_.data() + static_cast<std::size_t>(r) * (kBins + 1);
		int k = 0;
		for (int bin = 0; bin <= kBins; ++bin)
		{
			const float lo = -kPi + 2 * kPi * bin / kBins;
			while (k < n && b[k].az < lo) ++k;
			bins[bin] = k;
		}
	}
}

int RingSearch::nearest(int ring, const Query& q, float& best_d2, int exclude) const
{
	if (!points_ || ring < 0 || ring >= n_rings_) return -1;
	const Entry* b = entries_.data() + begin_[ring];
	const int n = static_cast<int>(begin_[ring + 1] - begin_[ring]);
	if (n == 0) return -1;
	// Every point of the ring is at least range * sin(elevation gap) from q (x - x^3/6 <= sin x).
	const float gap = std::min(std::max(elevation_lo_[ring] - q.elevation, q.elevation - elevation_hi_[ring]) - kAtanError, kPi / 2);
	if (gap > 0)
	{
		const float bound = q.range * (gap - gap * gap * gap / 6);
		if (bound * bound >= best_d2) return -1;
	}
	const int bin = std::clamp(static_cast<int>((q.az + kPi) * (kBins / (2 * kPi))), 0, kBins - 1);
	int hi = bin_start_[static_cast<std::size_t>(ring) * (kBins + 1) + bin];
	while (hi < n && b[hi].az < q.az) ++hi;
	if (hi == n) hi = 0;
	int lo = hi == 0 ? n - 1 : hi - 1;

	// Walk both ways (wrapping around) in turns, so the best distance shrinks early. While the
	// angular offset is below 90 deg, |q_xy x u| = rho_q sin(offset) bounds the distance from
	// below and grows with the offset: a direction stops once it exceeds the best.
	int best = -1;
	bool up = true, down = true;
	const auto visit = [&](int k) {
		const Entry& e = b[k];  // k is kept within [0, n) by the walk below
		const float along = q.p.x() * e.ux + q.p.y() * e.uy;
		const float across = q.p.x() * e.uy - q.p.y() * e.ux;
		if (along <= 0 || across * across >= best_d2) return false;
		const float dx = e.x - q.p.x(), dy = e.y - q.p.y(), dz = e.z - q.p.z();
		const float d2 = dx * dx + dy * dy + dz * dz;
		if (d2 < best_d2 && e.index != exclude)
		{
			best_d2 = d2;
			best = e.index;
		}
		return true;
	};
	for (int steps = 0; (up || down) && steps < n;)
	{
		if (up)
		{
			up = visit(hi);
			hi = hi + 1 == n ? 0 : hi + 1;
			++steps;
		}
		if (down && steps < n)
		{
			down = visit(lo);
			lo = lo == 0 ? n - 1 : lo - 1;
			++steps;
		}
	}
	return best;
}
}  // namespace vlo::loam
