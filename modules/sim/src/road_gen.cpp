// Random road profiles: curvature pieces with smooth transitions, grade as a few long waves.
#include <vlo/sim/rng.h>
#include <vlo/sim/road.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
struct Piece
{
	double start, end, curvature;
};

std::vector<Piece> curvaturePieces(const RoadStyle& st, double length, Rng& rng)
{
	std::vector<Piece> pieces;
	double s = 0;
	while (s < length)
	{
		if (st.straight_from < st.straight_to && s >= st.straight_from && s < st.straight_to)
		{
			pieces.push_back({s, st.straight_to, 0});
			s = st.straight_to;
			continue;
		}
		double len = rng.uniform(st.piece_min, st.piece_max);
		if (st.straight_from < st.straight_to && s < st.straight_from) len = std::min(len, st.straight_from - s);
		double k = 0;
		if (!rng.chance(st.straight_fraction))
			k = (rng.chance(0.5) ? 1 : -1) * std::exp(rng.uniform(std::log(st.min_curvature), std::log(st.max_curvature)));
		pieces.push_back({s, s + len, k});
		s += len;
	}
	return pieces;
}

/// Curvature at s: piece values blended linearly over 12 m around each change (no kinks).
double curvatureAt(const std::vector<Piece>& pieces, double s)
{
	constexpr double kBlend = 12.0;
	double k = 0, wsum = 0;
	for (const Piece& p : pieces)
	{
		if (s < p.start - kBlend || s > p.end + kBlend) continue;
		const double w = std::clamp(std::min(s - (p.start - kBlend / 2), (p.end + kBlend / 2) - s) / kBlend + 0.5, 0.0, 1.0);
		k += w * p.curvature, wsum += w;
	}
	return wsum > 0 ? k / wsum : 0;
}
}  // namespace

Road straightRoad(double length)
{
	std::vector<Station> st;
	for (double s = 0; s <= length; s += 1.0)
	{
		Station x;
		x.s = s, x.p.x() = s;
		st.push_back(x);
	}
	return Road(std::move(st));
}

Road generateRoad(const RoadStyle& style, double length, Rng& rng)
{
	const auto pieces = curvaturePieces(style, length, rng);
	double amp[3], lambda[3], phase[3];
	for (int i = 0; i < 3; ++i)
		amp[i] = style.grade_amplitude * rng.uniform(0.2, 0.5), lambda[i] = rng.uniform(150, 500),
		phase[i] = rng.uniform(0, 2 * M_PI);
	const bool corridor = style.straight_from < style.straight_to;
	auto gradeAt = [&](double s) {
		double g = 0;
		for (int i = 0; i < 3; ++i) g += amp[i] * std::sin(2 * M_PI * s / lambda[i] + phase[i]);
		if (!corridor) return g;
		// Level inside the corridor, easing in and out over 40 m.
		const double d = std::max(style.straight_from - s, s - style.straight_to);
		return g * std::clamp(d / 40.0, 0.0, 1.0);
	};
	std::vector<Station> st;
	Station cur;
	for (double s = 0; s <= length; s += 1.0)
	{
		cur.s = s;
		cur.curvature = curvatureAt(pieces, s);
		cur.grade = gradeAt(s);
		st.push_back(cur);
		// Midpoint integration to the next station.
		const double h = cur.heading + 0.5 * cur.curvature;
		cur.p += Eigen::Vector3d(std::cos(h), std::sin(h), gradeAt(s + 0.5));
		cur.heading += curvatureAt(pieces, s + 0.5);
	}
	return Road(std::move(st));
}
}  // namespace vlo::sim
