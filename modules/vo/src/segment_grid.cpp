#include <vlo/vo/segment_grid.h>

#include <algorithm>
#include <cmath>

namespace vlo::vo
{
namespace
{
/// Liang-Barsky: shrinks [u0, u1] of p + u d to the part inside the box; false if none is.
bool clip(const Vec2& p, const Vec2& d, const Vec2& lo, const Vec2& hi, double& u0, double& u1)
{
	for (int a = 0; a < 2; ++a)
	{
		if (std::abs(d[a]) < 1e-12)
		{
			if (p[a] < lo[a] || p[a] > hi[a]) return false;
			continue;
		}
		double ua = (lo[a] - p[a]) / d[a], ub = (hi[a] - p[a]) / d[a];
		if (ua > ub) std::swap(ua, ub);
		u0 = std::max(u0, ua);
		u1 = std::min(u1, ub);
	}
	return u0 <= u1;
}
}  // namespace

SegmentGrid::SegmentGrid(int width, int height, double cell)
	: cell_(cell),
	  cols_(std::max(1, static_cast<int>(std::ceil(width / cell)))),
	  rows_(std::max(1, static_cast<int>(std::ceil(height / cell)))),
	  items_(static_cast<std::size_t>(cols_ * rows_))
{
}

void SegmentGrid::add(double x, double y, int item)
{
	const int cx = static_cast<int>(std::floor(x / cell_)), cy = static_cast<int>(std::floor(y / cell_));
	if (cx < 0 || cy < 0 || cx >= cols_ || cy >= rows_) return;
	items_[static_cast<std::size_t>(cy * cols_ + cx)].push_back(item);
}

void SegmentGrid::markCells(const Vec2& p, const Vec2& q, double band)
{
	marked_.clear();
	// Only the part of the segment within `band` of the image can be near an item.
	const Vec2 d = q - p;
	double u0 = 0, u1 = 1;
	if (!clip(p, d, Vec2(-band, -band), Vec2(cols_ * cell_ + band, rows_ * cell_ + band), u0, u1)) return;
	Vec2 a = p + u0 * d, b = p + u1 * d;
	// Walk the cell columns (rows when steeper) and take, in each, the cells the band covers there.
	const int major = std::abs(b.x() - a.x()) >= std::abs(b.y() - a.y()) ? 0 : 1, minor = 1 - major;
	if (a[major] > b[major]) std::swap(a, b);
	const int n_major = major == 0 ? cols_ : rows_, n_minor = major == 0 ? rows_ : cols_;
	const double span = b[major] - a[major];
	const double slope = span > 1e-9 ? (b[minor] - a[minor]) / span : 0.0;
	const double reach = band * std::sqrt(1 + slope * slope);  // the band measured along the minor axis
	const auto index = [&](double v, int n) { return std::clamp(static_cast<int>(std::floor(v / cell_)), 0, n - 1); };
	const int m0 = index(a[major] - band, n_major), m1 = index(b[major] + band, n_major);
	for (int m = m0; m <= m1; ++m)
	{
		// The segment's minor coordinates across this column, its ends clamped to the segment.
		const double s0 = std::clamp(m * cell_, a[major], b[major]), s1 = std::clamp((m + 1) * cell_, a[major], b[major]);
		const double v0 = a[minor] + slope * (s0 - a[major]), v1 = a[minor] + slope * (s1 - a[major]);
		const int lo = index(std::min(v0, v1) - reach, n_minor), hi = index(std::max(v0, v1) + reach, n_minor);
		for (int k = lo; k <= hi; ++k) marked_.push_back(major == 0 ? k * cols_ + m : m * cols_ + k);
	}
}
}  // namespace vlo::vo
