// The residential street (scenario_residential.cpp): open between the houses and cluttered near the
// road, where the urban rows are a canyon of long facades.
#include <vlo/sim/config.h>
#include <vlo/sim/road.h>
#include <vlo/sim/scenarios.h>
#include <vlo/sim/world.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace vlo::sim;

namespace
{
struct View
{
	double beyond_20m = 0;  ///< share of level rays that reach farther than 20 m
	double depth_edges = 0;  ///< per 100 m of road and side: knee-high rays across, 0.25 m apart, whose range jumps by > 0.5 m
};

/// Rays from the right lane at the LiDAR's height along 300 m of a straight road.
View look(Scenario sc, uint64_t seed)
{
	const Road road = straightRoad(400);
	WorldSpec spec;
	spec.scenario = sc, spec.seed = seed;
	const World w = buildWorld(spec, road);
	std::size_t level = 0, far = 0, edges = 0;
	for (double x = 50; x < 350; x += 10)
	{
		for (int i = 0; i < 360; ++i)
		{
			const double az = 2 * M_PI * i / 360;
			double r = 100;
			w.raycast(Eigen::Vector3d(x, -1.75, 1.7), Eigen::Vector3d(std::cos(az), std::sin(az), 0), 100, r);
			++level, far += r > 20;
		}
	}
	for (double side : {-1.0, 1.0})
	{
		double last = -1;
		for (double x = 50; x < 350; x += 0.25)
		{
			double r = 100;
			w.raycast(Eigen::Vector3d(x, 0, 0.6), Eigen::Vector3d(0, side, 0), 100, r);
			edges += last >= 0 && std::abs(r - last) > 0.5;
			last = r;
		}
	}
	return {double(far) / level, edges / 6.0};
}
}  // namespace

TEST(Residential, IsAScenario)
{
	EXPECT_EQ(parseScenario("residential"), Scenario::Residential);
	EXPECT_EQ(scenarioName(Scenario::Residential), "residential");
}

// Measured on seeds 1-3: beyond 20 m 0.42-0.46 (urban) against 0.82-0.87; depth edges 27-31 against 50-52
// per 100 m (hedges, fence posts, driveways, bushes).
TEST(Residential, SeesBetweenTheHousesAndThingsAlongTheRoad)
{
	for (uint64_t seed : {1, 2, 3})
	{
		const View urban = look(Scenario::Urban, seed), residential = look(Scenario::Residential, seed);
		EXPECT_GT(residential.beyond_20m, 0.7) << seed;
		EXPECT_GT(residential.beyond_20m, 1.5 * urban.beyond_20m) << seed;
		EXPECT_GT(residential.depth_edges, 40) << seed;
		EXPECT_GT(residential.depth_edges, 1.4 * urban.depth_edges) << seed;
	}
}
