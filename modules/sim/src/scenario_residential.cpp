// A residential street (KITTI raw 2011_09_26_0013's kind): detached houses set back behind front
// yards, each yard closed to the sidewalk by a hedge, a fence on posts, a low wall or nothing (a
// driveway, often with a car), bushes and small trees in the yards, and the urban street's parked
// cars, lamps, trees plus sign posts and bollards on the sidewalks. Unlike the urban rows, the
// LiDAR sees between the houses and along the yards: small things at every distance, few long
// planes, as on the real street.
#include "placer.h"

#include <vlo/sim/props.h>
#include <vlo/sim/shapes.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
namespace
{
/// A hedge along x of the frame: overlapping bushes 0.8-1.8 m tall.
void addHedge(Placer& p, const Eigen::Isometry3d& f, double length)
{
	const double h = p.rng.uniform(0.8, 1.8), w = p.rng.uniform(0.5, 0.8);
	const int tex = p.pick(p.tex.foliages);
	for (double x = -length / 2 + 0.6; x < length / 2 - 0.3; x += p.rng.uniform(0.9, 1.4))
		addBlob(p.world, f * Eigen::Vector3d(x, 0, 0.45 * h), Eigen::Vector3d(0.8, w / 2, h / 2), 0.15, tex, p.rng);
}

/// A fence along x of the frame: posts every 2-2.5 m and two rails.
void addFence(Placer& p, const Eigen::Isometry3d& f, double length)
{
	const double h = p.rng.uniform(0.9, 1.4);
	const int tex = p.pick(p.tex.walls);
	const double step = p.rng.uniform(2.0, 2.5);
	for (double x = -length / 2; x <= length / 2 + 1e-9; x += step)
	{
		Eigen::Isometry3d post = f;
		post.translate(Eigen::Vector3d(x, 0, 0));
		addBox(p.world, post, 0.1, 0.1, h, tex, tex);
	}
	for (double z : {0.35 * h, 0.85 * h})
	{
		Eigen::Isometry3d rail = f;
		rail.translate(Eigen::Vector3d(0, 0, z));
		addBox(p.world, rail, length, 0.04, 0.1, tex, tex);
	}
}

/// What closes a yard of length `len` to the sidewalk, its frame on the yard's front edge.
void yardFront(Placer& p, const Eigen::Isometry3d& f, double len, double side, double s)
{
	const double k = p.rng.uniform(0, 1);
	if (k < 0.35)
		addHedge(p, f, len);
	else if (k < 0.6)
		addFence(p, f, len);
	else if (k < 0.75)
		addWall(p.world, f, len, p.rng.uniform(0.5, 1.0), 0.25, p.pick(p.tex.walls));
	else if (p.rng.chance(0.7))  // a driveway: often a car on it
	{
		const auto car = p.frameAt(s, side * (p.cs.clearance() + 3.5), M_PI / 2 + p.rng.uniform(-0.1, 0.1));
		if (p.fits(car, 4.6, 1.9, p.cs.clearance()))
		{
			const int c = p.rng.integer(0, static_cast<int>(p.tex.bodies.size()) - 1);
			addCar(p.world, car, p.tex.bodies[c], p.tex.cabins[c]);
			p.occupy(car, 4.6, 1.9);
		}
		return;
	}
	p.occupy(f, len, 0.6);
}

/// A house with a porch or a bay on its street side.
void addHouse(Placer& p, const Eigen::Isometry3d& f, double len, double depth, double side)
{
	const double height = p.rng.uniform(5, 10);
	addBuilding(p.world, f, len, depth, height, p.pick(p.tex.facades), p.tex.roof, 0.5 * p.rng.integer(0, 31));
	if (!p.rng.chance(0.7)) return;
	// The street side is -side in the frame's y (the frame is turned with the road).
	const double w = p.rng.uniform(2, std::min(5.0, len - 1)), d = p.rng.uniform(0.8, 2.0);
	Eigen::Isometry3d bay = f;
	bay.translate(Eigen::Vector3d(p.rng.uniform(-(len - w) / 2, (len - w) / 2), -side * (depth + d) / 2, 0));
	addBox(p.world, bay, w, d, p.rng.uniform(2.5, 3.2), p.pick(p.tex.facades), p.tex.roof);
}

void yardsAndHouses(Placer& p, double side, double s0, double s1)
{
	const double clear = p.cs.clearance();
	for (double s = s0 + p.rng.uniform(0, 6); s < s1;)
	{
		const double len = p.rng.uniform(14, 24);  // one plot along the street
		const double mid = s + len / 2;
		const auto front = p.frameAt(mid, side * (clear + 0.3), side > 0 ? 0 : M_PI);
		if (p.fits(front, len - 0.5, 0.6, clear - 0.1)) yardFront(p, front, len - 0.5, side, mid);
		// The house: set back 5-14 m behind the front, narrower than the plot.
		const double hl = p.rng.uniform(8, len - 3), depth = p.rng.uniform(8, 12), setback = p.rng.uniform(5, 14);
		const auto house = p.frameAt(mid + p.rng.uniform(-1, 1), side * (clear + setback + depth / 2));
		if (p.fits(house, hl + 0.4, depth + 4.4, clear + 3))
		{
			addHouse(p, house, hl, depth, side);
			p.occupy(house, hl + 0.4, depth + 4.4);
		}
		// Bushes and a small tree in the yard.
		for (int k = p.rng.integer(1, 3); k > 0; --k)
		{
			const auto b = p.frameAt(s + p.rng.uniform(1, len - 1), side * (clear + p.rng.uniform(1.2, setback - 0.5)));
			const double r = p.rng.uniform(0.4, 1.0);
			if (!p.fits(b, 2 * r, 2 * r, clear)) continue;
			addBlob(p.world, b.translation() + Eigen::Vector3d(0, 0, 0.5 * r), Eigen::Vector3d(r, r, 0.8 * r), 0.3,
				p.pick(p.tex.foliages), p.rng);
			p.occupy(b, 2 * r, 2 * r);
		}
		const auto t = p.frameAt(s + p.rng.uniform(2, len - 2), side * (clear + p.rng.uniform(2.5, setback)));
		if (p.rng.chance(0.5) && p.fits(t, 1.5, 1.5, clear))
		{
			addTree(p.world, t.translation(), p.rng.uniform(0.6, 1.0), p.pick(p.tex.barks), p.pick(p.tex.foliages), p.rng);
			p.occupy(t, 1.5, 1.5);
		}
		s += len + p.rng.uniform(0, 3);
	}
}

/// Sign posts, bollards and bins along the sidewalk's outer half.
void streetFurniture(Placer& p, double side, double s0, double s1)
{
	const double hw = p.cs.half_width;
	for (double s = s0 + p.rng.uniform(0, 8); s < s1; s += p.rng.uniform(4, 14))
	{
		auto f = p.frameAt(s, side * (hw + p.rng.uniform(0.4, p.cs.sidewalk - 0.4)));
		if (!p.fits(f, 0.5, 0.5, hw + 0.3)) continue;
		f.translate(Eigen::Vector3d(0, 0, p.cs.curb));
		const double k = p.rng.uniform(0, 1);
		if (k < 0.4)  // a sign on a post
		{
			addPrism(p.world, f, 0.04, 2.6, 8, p.tex.pole);
			Eigen::Isometry3d sign = f;
			sign.translate(Eigen::Vector3d(0, 0, 2.0));
			addBox(p.world, sign, 0.6, 0.03, 0.6, p.pick(p.tex.signs), p.tex.pole);
		}
		else if (k < 0.75)  // a bollard
			addPrism(p.world, f, 0.1, 0.9, 8, p.tex.pole);
		else  // a bin
			addBox(p.world, f, 0.6, 0.6, p.rng.uniform(0.9, 1.2), p.pick(p.tex.bodies), p.tex.pole);
		p.occupy(f, 0.5, 0.5);
	}
}
}  // namespace

void buildResidentialSide(Placer& p, double side, double s0, double s1)
{
	streetLampsAndTrees(p, side, s0, s1, 0, 0);
	streetFurniture(p, side, s0, s1);
	streetParking(p, side, s0, s1, 0, 0);
	yardsAndHouses(p, side, s0, s1);
}
}  // namespace vlo::sim
