// A tree-lined road: a dense row of trees whose crowns overhang the road, bushes right beside it,
// the trees scenario's sparser trees behind. At speed their foliage sweeps across much of the image
// (KITTI raw 2011_09_26_0013 beyond frame 47, where the VO lost track).
#include "placer.h"

#include <vlo/sim/props.h>
#include <vlo/sim/shapes.h>

namespace vlo::sim
{
void buildAvenueSide(Placer& p, double side, double s0, double s1)
{
	const double clear = p.cs.clearance();
	// The avenue's row: trunks 0.6-2.5 m off the shoulder every 3-7 m, large low crowns.
	plantTreeRow(p, side, s0, s1, {3, {3, 7}, {0.6, 2.5}, 1.0, {1.0, 1.5}});
	// Bushes between the trunks, at the camera's height, 0-1.5 m off the shoulder.
	for (double s = s0 + p.rng.uniform(0, 4); s < s1; s += p.rng.uniform(4, 10))
	{
		const double r = p.rng.uniform(0.6, 1.3);
		const auto f = p.frameAt(s, side * (clear + r + p.rng.uniform(0, 1.5)));
		if (!p.fits(f, r, r, clear)) continue;
		addBlob(p.world, f.translation() + Eigen::Vector3d(0, 0, 0.5 * r), Eigen::Vector3d(r, r * 1.3, 0.9 * r), 0.3,
			p.pick(p.tex.foliages), p.rng);
		p.occupy(f, r, r);
	}
	buildTreesSide(p, side, s0, s1);  // the rows behind (its near row fills what the avenue left free)
}
}  // namespace vlo::sim
