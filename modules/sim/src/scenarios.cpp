#include "placer.h"

#include <vlo/sim/scenarios.h>
#include <vlo/sim/textures.h>

#include <cmath>

namespace vlo::sim
{
Eigen::Isometry3d Placer::frameAt(double s, double lateral, double yaw) const
{
	Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
	f.translation() = road.point(s, lateral);
	f.rotate(Eigen::AngleAxisd(road.at(s).heading + yaw, Eigen::Vector3d::UnitZ()));
	return f;
}

template <class F>
bool Placer::forFootprint(const Eigen::Isometry3d& f, double sx, double sy, F&& fn) const
{
	for (double x = -sx / 2; x <= sx / 2 + 1e-9; x += std::min(0.5, sx / 2))
		for (double y = -sy / 2; y <= sy / 2 + 1e-9; y += std::min(0.5, sy / 2))
			if (!fn((f * Eigen::Vector3d(x, y, 0)).head<2>().eval())) return false;
	return true;
}

static int64_t cellKey(const Eigen::Vector2d& p)
{
	return static_cast<int64_t>(std::floor(p.x() * 2)) * 4000037LL + static_cast<int64_t>(std::floor(p.y() * 2));
}

bool Placer::occupied(const Eigen::Vector2d& p) const { return cells_.count(cellKey(p)) > 0; }

bool Placer::fits(const Eigen::Isometry3d& f, double sx, double sy, double clear) const
{
	return forFootprint(f, sx, sy, [&](const Eigen::Vector2d& p) {
		return !cells_.count(cellKey(p)) && road.nearest(p, clear) == nullptr;
	});
}

void Placer::occupy(const Eigen::Isometry3d& f, double sx, double sy)
{
	forFootprint(f, sx, sy, [&](const Eigen::Vector2d& p) {
		cells_.insert(cellKey(p));
		return true;
	});
}

CrossSection crossSectionFor(Scenario s)
{
	CrossSection cs;
	if (s == Scenario::Trees || s == Scenario::Avenue)
	{
		cs.half_width = 3.6, cs.lane = 3.3, cs.sidewalk = 0, cs.shoulder = 1.0;
	}
	return cs;
}

namespace
{
TexturePool makeTextures(World& w, Scenario sc, const CrossSection& cs, uint64_t seed)
{
	TexturePool t;
	RoadMarkings m;
	m.half_width = cs.half_width, m.lane = cs.lane, m.parking_bays = cs.half_width > cs.lane + 1;
	t.ground.road = w.addTexture(roadTexture(m, seed));
	t.ground.sidewalk = w.addTexture(sidewalkTexture(seed));
	t.ground.curb = w.addTexture(curbTexture(seed));
	t.ground.shoulder = w.addTexture(gravelTexture(seed));
	t.ground.verge = w.addTexture(grassTexture(seed + 1, 105));
	t.ground.terrain = w.addTexture(grassTexture(seed + 2, sc == Scenario::Trees || sc == Scenario::Avenue ? 95 : 115));
	for (int i = 0; i < 3; ++i) t.barks.push_back(w.addTexture(barkTexture(seed + 10 + i)));
	for (int i = 0; i < 4; ++i) t.foliages.push_back(w.addTexture(foliageTexture(seed + 20 + i)));
	if (sc == Scenario::Trees || sc == Scenario::Avenue) return t;
	for (int i = 0; i < 8; ++i) t.facades.push_back(w.addTexture(facadeTexture(seed + 30 + i)));
	for (int i = 0; i < 5; ++i)
	{
		t.bodies.push_back(w.addTexture(carBodyTexture(seed + 40 + i)));
		t.cabins.push_back(w.addTexture(carCabinTexture(seed + 40 + i)));
	}
	for (int i = 0; i < 3; ++i) t.signs.push_back(w.addTexture(signTexture(seed + 50 + i)));
	for (int i = 0; i < 2; ++i) t.walls.push_back(w.addTexture(gardenWallTexture(seed + 60 + i)));
	t.roof = w.addTexture(roofTexture(seed));
	t.pole = w.addTexture(poleTexture(seed));
	if (sc == Scenario::Corridor)
		for (int i = 0; i < 4; ++i) t.murals.push_back(w.addTexture(muralTexture(seed + 70 + i)));
	return t;
}
}  // namespace

World buildWorld(const WorldSpec& spec, const Road& road)
{
	World w;
	const CrossSection cs = crossSectionFor(spec.scenario);
	Placer p(w, road, cs, spec.seed, "world layout");
	p.tex = makeTextures(w, spec.scenario, cs, spec.seed);
	buildStreet(w, road, cs, p.tex.ground, 0, road.length());
	const double L = road.length();
	if (spec.scenario == Scenario::Loop)
		buildLoopSides(p, spec.turning_places, spec.park_from, spec.park_to);
	else if (spec.scenario == Scenario::Facades)
		buildFacadeStreet(p, spec.facade_period, 0, L);
	else
		for (double side : {-1.0, 1.0})
		{
			if (spec.scenario == Scenario::Trees)
				buildTreesSide(p, side, 0, L);
			else if (spec.scenario == Scenario::Avenue)
				buildAvenueSide(p, side, 0, L);
			else if (spec.scenario == Scenario::Residential)
				buildResidentialSide(p, side, 0, L);
			else if (spec.scenario == Scenario::Corridor)
				buildUrbanSide(p, side, 0, L, spec.corridor_from, spec.corridor_to);
			else
				buildUrbanSide(p, side, 0, L, 0, 0);
		}
	if (spec.scenario == Scenario::Corridor) buildCorridorWalls(p, spec.corridor_from, spec.corridor_to);
	// Terrain last: it skips what the road and the buildings cover.
	const double covered = cs.half_width + (cs.sidewalk > 0 ? cs.sidewalk : cs.shoulder) - 0.3;
	// The facades' street is flat all along: its ground repeats with the facades.
	const double relief = spec.scenario == Scenario::Facades ? 0 : 1;
	buildTerrain(w, road, p.tex.ground.terrain, 90, spec.seed, relief,
		[&](const Eigen::Vector2d& xy) { return p.occupied(xy) || road.nearest(xy, covered) != nullptr; });
	return w;
}
}  // namespace vlo::sim
