#pragma once
// Seeded worlds around a road, per scenario.
#include <vlo/sim/config.h>
#include <vlo/sim/road.h>
#include <vlo/sim/street.h>
#include <vlo/sim/world.h>

namespace vlo::sim
{
struct WorldSpec
{
	Scenario scenario = Scenario::Urban;
	uint64_t seed = 1;
	/// Arc-length interval of the corridor's walls (corridor scenario only).
	double corridor_from = 0, corridor_to = 0;
	/// Loop: where vehicles turn around (parking lanes kept free) and the outside's park (circuit.h).
	std::vector<double> turning_places;
	double park_from = 0, park_to = 0;
	/// Facades: the street's identical unit repeats every this many metres.
	double facade_period = 24;
};

CrossSection crossSectionFor(Scenario s);
/// The road's driving lane offset (right lane of a two-lane road).
constexpr double kLaneOffset = -1.75;

/// Ground, road and roadside objects along the whole road.
World buildWorld(const WorldSpec& spec, const Road& road);
}  // namespace vlo::sim
