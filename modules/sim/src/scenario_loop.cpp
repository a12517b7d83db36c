// The circuit's roadsides: urban rows all round, a park (trees only) along part of the outside, and
// the parking lanes kept free where the vehicle turns around.
#include "placer.h"

namespace vlo::sim
{
void buildLoopSides(Placer& p, const std::vector<double>& turning_places, double park_from, double park_to)
{
	// A U-turn sweeps both parking lanes from 16 m before the turning place to 4 m after it.
	const double parking = (p.cs.lane + p.cs.half_width) / 2;
	for (double t : turning_places)
		for (double side : {-1.0, 1.0}) p.occupy(p.frameAt(t - 6, side * parking), 28, 2.2);
	const double L = p.road.length();
	buildUrbanSide(p, 1, 0, L, 0, 0);  // inside the block (the circuit turns left)
	buildUrbanSide(p, -1, 0, L, park_from, park_to);
	buildTreesSide(p, -1, park_from, park_to);
}
}  // namespace vlo::sim
