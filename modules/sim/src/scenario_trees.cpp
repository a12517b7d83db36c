// Country road: rows of irregular trees and bushes, nothing planar but the ground.
#include "placer.h"

#include <vlo/sim/props.h>
#include <vlo/sim/shapes.h>

#include <cmath>

namespace vlo::sim
{
void plantTreeRow(Placer& p, double side, double s0, double s1, const TreeRow& row)
{
	const double clear = p.cs.clearance();
	for (double s = s0 + p.rng.uniform(0, row.first); s < s1; s += p.rng.uniform(row.gap[0], row.gap[1]))
	{
		const auto f = p.frameAt(s, side * (clear + p.rng.uniform(row.off[0], row.off[1])));
		if (!p.fits(f, row.footprint, row.footprint, clear)) continue;
		addTree(p.world, f.translation(), p.rng.uniform(row.size[0], row.size[1]), p.pick(p.tex.barks), p.pick(p.tex.foliages), p.rng);
		p.occupy(f, row.footprint, row.footprint);
	}
}

void buildTreesSide(Placer& p, double side, double s0, double s1)
{
	const double clear = p.cs.clearance();
	// Near row: irregular spacing, 1-10 m off the shoulder; sparser trees further away, and bushes.
	plantTreeRow(p, side, s0, s1, {5, {3.5, 9}, {1, 10}, 2.0, {0.7, 1.3}});
	plantTreeRow(p, side, s0, s1, {8, {6, 14}, {12, 35}, 2.5, {0.9, 1.5}});
	for (double s = s0 + p.rng.uniform(0, 8); s < s1; s += p.rng.uniform(8, 20))
	{
		const auto f = p.frameAt(s, side * (clear + p.rng.uniform(0.5, 6)));
		const double r = p.rng.uniform(0.5, 1.2);
		if (!p.fits(f, 2 * r, 2 * r, clear)) continue;
		addBlob(p.world, f.translation() + Eigen::Vector3d(0, 0, 0.4 * r), Eigen::Vector3d(r, r * 1.2, 0.8 * r), 0.3,
			p.pick(p.tex.foliages), p.rng);
		p.occupy(f, 2 * r, 2 * r);
	}
}
}  // namespace vlo::sim
