// Urban roadsides: rows of buildings with gaps (garden walls, trees), parked cars, street lamps
// (the street's parking and lamps also line the residential scenario).
// Also the corridor's walls.
#include "placer.h"

#include <vlo/sim/props.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
bool inSkip(double a, double b, double skip_from, double skip_to) { return skip_from < skip_to && b > skip_from && a < skip_to; }

void buildings(Placer& p, double side, double s0, double s1, double skip_from, double skip_to)
{
	const double clear = p.cs.clearance();
	double s = s0;
	while (s < s1)
	{
		const bool yard = p.rng.chance(0.2);
		const double gap = yard ? p.rng.uniform(8, 15) : p.rng.uniform(0.5, 5);
		if (yard && !inSkip(s, s + gap, skip_from, skip_to))
		{
			// Garden wall along the yard, and a tree behind it.
			const auto f = p.frameAt(s + gap / 2, side * (clear + 0.6), side > 0 ? 0 : M_PI);
			if (p.fits(f, gap - 1, 0.4, clear))
			{
				addWall(p.world, f, gap - 1, p.rng.uniform(1.0, 2.2), 0.3, p.pick(p.tex.walls));
				p.occupy(f, gap - 1, 0.4);
			}
			const auto t = p.frameAt(s + gap / 2, side * (clear + 4));
			if (p.fits(t, 2, 2, clear))
			{
				addTree(p.world, t.translation(), p.rng.uniform(0.8, 1.2), p.pick(p.tex.barks), p.pick(p.tex.foliages), p.rng);
				p.occupy(t, 2, 2);
			}
		}
		s += gap;
		double len = p.rng.uniform(8, 24);
		const double depth = p.rng.uniform(8, 16), height = p.rng.uniform(6, 20), setback = p.rng.uniform(0.3, 4);
		if (inSkip(s, s + len, skip_from, skip_to))
		{
			s = std::max(s + 1, skip_to);
			continue;
		}
		for (int attempt = 0; attempt < 2; ++attempt, len *= 0.6)
		{
			const auto f = p.frameAt(s + len / 2, side * (clear + setback + depth / 2));
			if (!p.fits(f, len + 0.4, depth + 0.4, clear)) continue;
			addBuilding(p.world, f, len, depth, height, p.pick(p.tex.facades), p.tex.roof, 0.5 * p.rng.integer(0, 31));
			p.occupy(f, len + 0.4, depth + 0.4);
			break;
		}
		s += len;
	}
}

}  // namespace

void streetParking(Placer& p, double side, double s0, double s1, double skip_from, double skip_to)
{
	const double lat = side * (p.cs.lane + p.cs.half_width) / 2;
	for (double s = s0 + p.rng.uniform(0, 6); s < s1; s += p.rng.uniform(5.5, 7.5))
	{
		if (!p.rng.chance(0.55) || inSkip(s - 3, s + 3, skip_from, skip_to)) continue;
		const auto f = p.frameAt(s, lat + p.rng.uniform(-0.15, 0.15), (side > 0 ? M_PI : 0) + p.rng.uniform(-0.04, 0.04));
		// Clear of the driving lanes of every part of the road (crossings, loops).
		if (!p.fits(f, 4.6, 1.9, p.cs.lane + 0.2)) continue;
		const int k = p.rng.integer(0, static_cast<int>(p.tex.bodies.size()) - 1);
		addCar(p.world, f, p.tex.bodies[k], p.tex.cabins[k]);
		p.occupy(f, 4.6, 1.9);
	}
}

void streetLampsAndTrees(Placer& p, double side, double s0, double s1, double skip_from, double skip_to)
{
	const double hw = p.cs.half_width;
	for (double s = s0 + p.rng.uniform(0, 20); s < s1; s += p.rng.uniform(22, 38))
	{
		if (inSkip(s - 2, s + 2, skip_from, skip_to)) continue;
		const auto f = p.frameAt(s, side * (hw + 0.5), side > 0 ? 0 : M_PI);
		if (!p.fits(f, 0.4, 0.4, hw + 0.3)) continue;
		const int sign = p.rng.chance(0.4) ? p.pick(p.tex.signs) : -1;
		Eigen::Isometry3d onCurb = f;
		onCurb.translate(Eigen::Vector3d(0, 0, p.cs.curb));
		addPole(p.world, onCurb, p.rng.uniform(6, 8), p.tex.pole, sign);
		p.occupy(f, 0.4, 0.4);
	}
	for (double s = s0 + p.rng.uniform(0, 10); s < s1; s += p.rng.uniform(12, 30))
	{
		if (!p.rng.chance(0.4) || inSkip(s - 3, s + 3, skip_from, skip_to)) continue;
		const auto f = p.frameAt(s, side * (hw + p.cs.sidewalk - 0.9));
		if (!p.fits(f, 1.2, 1.2, hw + 0.5)) continue;
		addTree(p.world, f.translation() + Eigen::Vector3d(0, 0, p.cs.curb), p.rng.uniform(0.9, 1.2), p.pick(p.tex.barks),
			p.pick(p.tex.foliages), p.rng);
		p.occupy(f, 1.2, 1.2);
	}
}
void buildUrbanSide(Placer& p, double side, double s0, double s1, double skip_from, double skip_to)
{
	buildings(p, side, s0, s1, skip_from, skip_to);
	streetParking(p, side, s0, s1, skip_from, skip_to);
	streetLampsAndTrees(p, side, s0, s1, skip_from, skip_to);
}

void buildCorridorWalls(Placer& p, double s0, double s1)
{
	// 32 m panels, 8 m tall, flush with each other: one smooth plane per side, textured richly.
	const double lat = p.cs.clearance() + 0.25;
	for (double side : {-1.0, 1.0})
		for (double s = s0; s < s1; s += 32)
		{
			const double len = std::min(32.0, s1 - s);
			const auto f = p.frameAt(s + len / 2, side * lat, side > 0 ? 0 : M_PI);
			addWall(p.world, f, len, 8.0, 0.5, p.pick(p.tex.murals));
			p.occupy(f, len, 0.5);
		}
}
}  // namespace vlo::sim
