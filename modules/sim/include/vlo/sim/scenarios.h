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
};

CrossSection crossSectionFor(Scenario s);
/// The road's driving lane offset (right lane of a two-lane road).
constexpr double kLaneOffset = -1.75;

/// Ground, road and roadside objects along the whole road.
World buildWorld(const WorldSpec& spec, const Road& road);
}  // namespace vlo::sim
