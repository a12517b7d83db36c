// Country road: rows of irregular trees and bushes, nothing planar but the ground.
#include "placer.h"

#include <vlo/sim/props.h>
#include <vlo/sim/shapes.h>

#include <cmath>

namespace vlo::sim
{
void buildTreesSide(Placer& p, double side, double s0, double s1)
{
	const double clear = p.cs.clearance();
	// Near row: irregular spacing, 1-10 m off the shoulder.
	for (double s = s0 + p.rng.uniform(0, 5); s < s1; s += p.rng.uniform(3.5, 9))
	{
		const auto f = p.frameAt(s, side * (clear + p.rng.uniform(1, 10)));
		if (!p.fits(f, 2.0, 2.0, clear)) continue;
		addTree(p.world, f.translation(), p.rng.uniform(0.7, 1.3), p.pick(p.tex.barks), p.pick(p.tex.foliages), p.rng);
		p.occupy(f, 2.0, 2.0);
	}
	// Sparser trees further away, and bushes.
	for (double s = s0 + p.rng.uniform(0, 8); s < s1; s += p.rng.uniform(6, 14))
	{
		const auto f = p.frameAt(s, side * (clear + p.rng.uniform(12, 35)));
		if (!p.fits(f, 2.5, 2.5, clear)) continue;
		addTree(p.world, f.translation(), p.rng.uniform(0.9, 1.5), p.pick(p.tex.barks), p.pick(p.tex.foliages), p.rng);
		p.occupy(f, 2.5, 2.5);
	}
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
