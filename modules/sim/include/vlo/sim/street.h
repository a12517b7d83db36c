#pragma once
// The ground along a road: asphalt, curbs and sidewalks (or gravel shoulders), the verge sloping
// down into the terrain, and a terrain height field around the whole road.
#include <vlo/sim/road.h>
#include <vlo/sim/world.h>

#include <functional>

namespace vlo::sim
{
/// Cross-section, metres from the centre line (symmetric).
struct CrossSection
{
	double half_width = 5.7;  ///< asphalt edge
	double lane = 3.5;  ///< driving lane edge (parking lane beyond it when half_width > lane + 1)
	double sidewalk = 3.0;  ///< raised sidewalk width; 0: gravel shoulder instead
	double curb = 0.15;  ///< sidewalk height
	double shoulder = 1.0;  ///< gravel width when there is no sidewalk
	/// Lateral distance from the centre line that objects must keep clear of.
	double clearance() const { return half_width + (sidewalk > 0 ? sidewalk : shoulder) + 0.3; }
};

struct GroundTextures
{
	int road = -1, sidewalk = -1, curb = -1, shoulder = -1, verge = -1, terrain = -1;
};

/// Lays the road between arc lengths [s0, s1). Where another part of the same road passes within
/// reach (a loop or a crossing of a KITTI drive), the later part is left out so surfaces never overlap.
void buildStreet(World& w, const Road& road, const CrossSection& cs, const GroundTextures& tex, double s0, double s1);

/// Terrain on a 4 m grid within `radius` of the road: slightly below the road near it (the verges
/// cut into it), undulating far from it by up to `relief` metres (0: flat). Cells whose corners and
/// centre are all `hidden` (under the road or a building) are left out: they would only cost
/// rendering time.
void buildTerrain(World& w, const Road& road, int tex, double radius, uint64_t seed, double relief,
	const std::function<bool(const Eigen::Vector2d&)>& hidden);
}  // namespace vlo::sim
