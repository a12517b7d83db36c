// A street of identical facades: one unit (building, street lamp, parked car, street tree per side)
// repeated every `period` metres, the place recogniser's trap: the same place seen again where
// there is no revisit.
#include "placer.h"

#include <vlo/sim/props.h>

#include <cmath>

namespace vlo::sim
{
void buildFacadeStreet(Placer& p, double period, double s0, double s1)
{
	// The unit, drawn once.
	const double gap = 4, length = period - gap, depth = p.rng.uniform(10, 14), height = p.rng.uniform(10, 16);
	const double setback = p.rng.uniform(0.5, 2), u_offset = 0.5 * p.rng.integer(0, 31);
	const int facade = p.pick(p.tex.facades), sign = p.pick(p.tex.signs);
	const int car = p.rng.integer(0, static_cast<int>(p.tex.bodies.size()) - 1);
	const double car_at = p.rng.uniform(3, period - 3), tree_at = p.rng.uniform(1, period - 1);
	const int bark = p.pick(p.tex.barks), foliage = p.pick(p.tex.foliages);
	const uint64_t tree_seed = p.rng.next();
	const double clear = p.cs.clearance(), hw = p.cs.half_width;
	for (double s = s0; s + period <= s1; s += period)
		for (double side : {-1.0, 1.0})
		{
			const auto b = p.frameAt(s + length / 2, side * (clear + setback + depth / 2));
			addBuilding(p.world, b, length, depth, height, facade, p.tex.roof, u_offset);
			p.occupy(b, length + 0.4, depth + 0.4);
			Eigen::Isometry3d pole = p.frameAt(s + length + gap / 2, side * (hw + 0.5), side > 0 ? 0 : M_PI);
			pole.translate(Eigen::Vector3d(0, 0, p.cs.curb));
			addPole(p.world, pole, 7, p.tex.pole, sign);
			addCar(p.world, p.frameAt(s + car_at, side * (p.cs.lane + hw) / 2, side > 0 ? M_PI : 0), p.tex.bodies[car],
				p.tex.cabins[car]);
			Rng same_tree(tree_seed);  // the same crown every time
			addTree(p.world, p.frameAt(s + tree_at, side * (hw + p.cs.sidewalk - 0.9)).translation() + Eigen::Vector3d(0, 0, p.cs.curb),
				1.0, bark, foliage, same_tree);
		}
}
}  // namespace vlo::sim
