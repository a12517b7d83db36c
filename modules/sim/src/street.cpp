#include <vlo/sim/rng.h>
#include <vlo/sim/street.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
constexpr double kLoopExclude = 30.0;  // stations closer than this along the road are "the same part"
constexpr double kTerrainDrop = 0.25;  // terrain below the road surface near the road
constexpr double kVergeDrop = 0.6;  // verges end this far below the road, under the terrain

/// True if the point at lateral offset `lat` of station s lies on another part of the road.
bool covered(const Road& road, double s, double lat, double radius)
{
	const Eigen::Vector3d p = road.point(s, lat);
	return road.nearest(p.head<2>(), radius, s, kLoopExclude) != nullptr;
}

/// One side strip between lateral offsets a and b (b further out), heights ha, hb above the road.
void strip(World& w, const Road& road, int tex, double s, double a, double b, double ha, double hb, double side, double uscale)
{
	const Texture& t = w.texture(tex);
	const Eigen::Vector3d a0 = road.point(s, side * a, ha), a1 = road.point(s + 1, side * a, ha);
	const Eigen::Vector3d b0 = road.point(s, side * b, hb), b1 = road.point(s + 1, side * b, hb);
	const double u0 = s * uscale / t.width_m, u1 = (s + 1) * uscale / t.width_m;
	const double va = a / t.height_m, vb = b / t.height_m;
	// Counter-clockwise seen from above on both sides.
	if (side > 0)
		w.addQuad(tex, {a0, u0, va}, {a1, u1, va}, {b1, u1, vb}, {b0, u0, vb});
	else
		w.addQuad(tex, {b0, u0, vb}, {b1, u1, vb}, {a1, u1, va}, {a0, u0, va});
}
}  // namespace

void buildStreet(World& w, const Road& road, const CrossSection& cs, const GroundTextures& tex, double s0, double s1)
{
	const double hw = cs.half_width;
	const Texture& rt = w.texture(tex.road);
	for (double s = std::max(0.0, s0); s + 1 <= std::min(s1, road.length()); s += 1.0)
	{
		if (!covered(road, s + 0.5, 0, hw))
		{
			const double u0 = s / rt.width_m, u1 = (s + 1) / rt.width_m;
			w.addQuad(tex.road, {road.point(s, -hw), u0, 0}, {road.point(s + 1, -hw), u1, 0}, {road.point(s + 1, hw), u1, 1},
				{road.point(s, hw), u0, 1});
		}
		for (double side : {-1.0, 1.0})
		{
			const double outer = hw + (cs.sidewalk > 0 ? cs.sidewalk : cs.shoulder);
			if (covered(road, s + 0.5, side * (hw + outer) / 2, (outer + hw) / 2 + 0.5)) continue;
			if (cs.sidewalk > 0)
			{
				// Curb face: a strip whose two edges are at the same offset, different heights.
				const Texture& ct = w.texture(tex.curb);
				const Eigen::Vector3d b0 = road.point(s, side * hw), b1 = road.point(s + 1, side * hw);
				const Eigen::Vector3d t0 = road.point(s, side * hw, cs.curb), t1 = road.point(s + 1, side * hw, cs.curb);
				const double u0 = s / ct.width_m, u1 = (s + 1) / ct.width_m, v1 = cs.curb / ct.height_m;
				if (side > 0)
					w.addQuad(tex.curb, {b1, u1, 0}, {b0, u0, 0}, {t0, u0, v1}, {t1, u1, v1});
				else
					w.addQuad(tex.curb, {b0, u0, 0}, {b1, u1, 0}, {t1, u1, v1}, {t0, u0, v1});
				strip(w, road, tex.sidewalk, s, hw, outer, cs.curb, cs.curb, side, 1.0);
				strip(w, road, tex.verge, s, outer, outer + 2.5, cs.curb, -kVergeDrop, side, 1.0);
			}
			else
			{
				strip(w, road, tex.shoulder, s, hw, outer, -0.02, -0.03, side, 1.0);
				strip(w, road, tex.verge, s, outer, outer + 3.0, -0.03, -kVergeDrop, side, 1.0);
			}
		}
	}
}

void buildTerrain(World& w, const Road& road, int tex, double radius, uint64_t seed, double relief,
	const std::function<bool(const Eigen::Vector2d&)>& hidden)
{
	constexpr double kCell = 4.0;
	Eigen::Vector2d lo(1e18, 1e18), hi(-1e18, -1e18);
	for (const auto& st : road.stations()) lo = lo.cwiseMin(st.p.head<2>()), hi = hi.cwiseMax(st.p.head<2>());
	lo.array() -= radius, hi.array() += radius;
	const int nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / kCell)) + 1;
	const int ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / kCell)) + 1;
	// Height per grid vertex, NaN where no road is within reach.
	std::vector<double> z(static_cast<std::size_t>(nx) * ny, std::nan(""));
	for (int j = 0; j < ny; ++j)
		for (int i = 0; i < nx; ++i)
		{
			const Eigen::Vector2d xy = lo + kCell * Eigen::Vector2d(i, j);
			const Station* st = road.nearest(xy, radius + kCell);
			if (!st) continue;
			const double d = (st->p.head<2>() - xy).norm();
			// Far from the road: gentle random relief (+-relief m), fading in from 20 m to 50 m.
			const double bump = relief * 2 * (valueNoise(xy.x() / 40, xy.y() / 40, seed) - 0.5) * std::clamp((d - 20) / 30, 0.0, 1.0);
			z[j * nx + i] = st->p.z() - kTerrainDrop + bump;
		}
	const Texture& t = w.texture(tex);
	auto V = [&](int i, int j) {
		const Eigen::Vector2d xy = lo + kCell * Eigen::Vector2d(i, j);
		return Vertex{Eigen::Vector3d(xy.x(), xy.y(), z[j * nx + i]), xy.x() / t.width_m, xy.y() / t.height_m};
	};
	for (int j = 0; j + 1 < ny; ++j)
		for (int i = 0; i + 1 < nx; ++i)
		{
			if (std::isnan(z[j * nx + i]) || std::isnan(z[j * nx + i + 1]) || std::isnan(z[(j + 1) * nx + i]) ||
				std::isnan(z[(j + 1) * nx + i + 1]))
				continue;
			const Eigen::Vector2d c = lo + kCell * Eigen::Vector2d(i, j);
			if (hidden(c) && hidden(c + Eigen::Vector2d(kCell, 0)) && hidden(c + Eigen::Vector2d(0, kCell)) &&
				hidden(c + Eigen::Vector2d(kCell, kCell)) && hidden(c + Eigen::Vector2d(kCell / 2, kCell / 2)))
				continue;
			w.addQuad(tex, V(i, j), V(i + 1, j), V(i + 1, j + 1), V(i, j + 1));
		}
}
}  // namespace vlo::sim
