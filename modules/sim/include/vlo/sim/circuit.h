#pragma once
// A closed circuit for drives that come back to the same places (loop closure): a city block of
// about 500 m with tight corners, and the path a vehicle drives around it, lap after lap, turning
// around at a wide place to drive the other way.
#include <vlo/sim/road.h>

#include <vector>

namespace vlo::sim
{
struct Circuit
{
	/// Closed, counter-clockwise; arc length 0 is the start, in the middle of a straight, heading
	/// along world x. Stations every 0.5 m (the tight corners need more than 1 m).
	Road road;
	/// Arc lengths where a vehicle turns around: straight from 20 m before to 8 m after, and the
	/// parking lanes kept free there.
	std::vector<double> turning_places;
	/// Arc-length stretch where the outside (right) of the circuit is a park: trees instead of buildings.
	double park_from = 0, park_to = 0;
};

/// The city-block circuit, the same for every seed: 504 m a lap (a multiple of the ground textures'
/// 24 m, so that they join seamlessly), five left-hand corners of radius 12.6 to 29 m and an S-bend,
/// and a grade that waves gently (up to 2.5 %) and closes on itself.
Circuit cityBlockCircuit();

/// The forward distance (m) after which a vehicle that starts at arc length 0 turns around, when it
/// should do so after `laps` laps: that of the turning place nearest to that point; 0 (never) when
/// `laps` <= 0.
double turnaroundDistance(const Circuit& c, double laps);

/// The path the vehicle drives, `distance` metres long, stations every 0.25 m: laps in the right lane
/// from arc length 0 and, if `turn_at` > 0, a U-turn there across both parking lanes (radius 3.9 m,
/// as tight as a car turns), then laps the other way in the other lane.
Road lapPath(const Circuit& c, double distance, double turn_at);
}  // namespace vlo::sim
