#include <vlo/sim/road.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }
}  // namespace

Road::Road(std::vector<Station> stations, bool closed) : st_(std::move(stations)), closed_(closed)
{
	for (std::size_t i = 0; i < st_.size(); ++i)
	{
		const auto& p = st_[i].p;
		grid_[key(std::llround(std::floor(p.x() / kCell)), std::llround(std::floor(p.y() / kCell)))].push_back(int(i));
	}
}

double Road::arcDistance(double a, double b) const
{
	const double d = std::abs(a - b);
	if (!closed_ || length() <= 0) return d;
	const double m = std::fmod(d, length());
	return std::min(m, length() - m);
}

Station Road::at(double s) const
{
	if (st_.empty()) return {};
	if (closed_ && length() > 0 && (s < 0 || s >= length()))
	{
		Station r = at(s - std::floor(s / length()) * length());
		r.s = s;
		return r;
	}
	if (s <= st_.front().s) return st_.front();
	if (s >= st_.back().s) return st_.back();
	const auto it = std::upper_bound(st_.begin(), st_.end(), s, [](double v, const Station& x) { return v < x.s; });
	const Station& b = *it;
	const Station& a = *(it - 1);
	const double t = (s - a.s) / std::max(1e-9, b.s - a.s);
	Station r;
	r.s = s;
	r.p = a.p + t * (b.p - a.p);
	r.heading = a.heading + t * wrapAngle(b.heading - a.heading);
	r.grade = a.grade + t * (b.grade - a.grade);
	r.curvature = a.curvature + t * (b.curvature - a.curvature);
	return r;
}

Eigen::Vector3d Road::point(double s, double lateral, double up) const
{
	const Station st = at(s);
	return st.p + Eigen::Vector3d(-std::sin(st.heading) * lateral, std::cos(st.heading) * lateral, up);
}

const Station* Road::nearest(const Eigen::Vector2d& xy, double radius, double s_self, double exclude) const
{
	const Station* best = nullptr;
	double best_d2 = radius * radius;
	const int64_t x0 = std::llround(std::floor((xy.x() - radius) / kCell)), x1 = std::llround(std::floor((xy.x() + radius) / kCell));
	const int64_t y0 = std::llround(std::floor((xy.y() - radius) / kCell)), y1 = std::llround(std::floor((xy.y() + radius) / kCell));
	for (int64_t ix = x0; ix <= x1; ++ix)
		for (int64_t iy = y0; iy <= y1; ++iy)
		{
			const auto it = grid_.find(key(ix, iy));
			if (it == grid_.end()) continue;
			for (int i : it->second)
			{
				const Station& s = st_[i];
				if (exclude > 0 && arcDistance(s.s, s_self) <= exclude) continue;
				const double d2 = (s.p.head<2>() - xy).squaredNorm();
				if (d2 < best_d2) best_d2 = d2, best = &s;
			}
		}
	return best;
}

Road roadThrough(const std::vector<Eigen::Vector3d>& points, double extend, double step)
{
	// Drop repeated points (the vehicle standing still), then resample every `step` metres.
	std::vector<Eigen::Vector3d> pts;
	for (const auto& p : points)
		if (pts.empty() || (p - pts.back()).head<2>().norm() > 0.05) pts.push_back(p);
	if (pts.size() < 2) pts = {Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0)};
	auto dirAt = [&](std::size_t a, std::size_t b) { return (pts[b] - pts[a]).head<2>().normalized().eval(); };
	const Eigen::Vector2d d0 = dirAt(0, std::min<std::size_t>(pts.size() - 1, 5));
	const Eigen::Vector2d d1 = dirAt(pts.size() - std::min<std::size_t>(pts.size(), 6), pts.size() - 1);
	std::vector<Eigen::Vector3d> poly;
	for (double e = extend; e > 0; e -= 5) poly.push_back(pts.front() - Eigen::Vector3d(d0.x(), d0.y(), 0) * e);
	poly.insert(poly.end(), pts.begin(), pts.end());
	for (double e = 5; e <= extend; e += 5) poly.push_back(pts.back() + Eigen::Vector3d(d1.x(), d1.y(), 0) * e);

	std::vector<Station> st;
	double s = 0, next = 0;
	for (std::size_t i = 0; i + 1 < poly.size(); ++i)
	{
		const double len = (poly[i + 1] - poly[i]).head<2>().norm();
		for (; next <= s + len; next += step)
		{
			const double t = (next - s) / std::max(len, 1e-9);
			Station x;
			x.s = next;
			x.p = poly[i] + t * (poly[i + 1] - poly[i]);
			st.push_back(x);
		}
		s += len;
	}
	// Headings and grades from smoothed differences (KITTI positions carry centimetre jitter).
	for (std::size_t i = 0; i < st.size(); ++i)
	{
		const std::size_t a = i >= 3 ? i - 3 : 0, b = std::min(st.size() - 1, i + 3);
		const Eigen::Vector3d d = st[b].p - st[a].p;
		st[i].heading = std::atan2(d.y(), d.x());
		st[i].grade = d.z() / std::max(1e-6, d.head<2>().norm());
	}
	for (std::size_t i = 1; i + 1 < st.size(); ++i)
		st[i].curvature = wrapAngle(st[i + 1].heading - st[i - 1].heading) / (2 * step);
	return Road(std::move(st));
}
}  // namespace vlo::sim
