#pragma once
// Shared state while populating a world: textures, free space, and frames along the road.
#include <vlo/sim/rng.h>
#include <vlo/sim/road.h>
#include <vlo/sim/street.h>
#include <vlo/sim/world.h>

#include <Eigen/Geometry>
#include <unordered_set>
#include <vector>

namespace vlo::sim
{
struct TexturePool
{
	GroundTextures ground;
	std::vector<int> facades, bodies, cabins, barks, foliages, signs, walls, murals;
	int roof = -1, pole = -1;
};

class Placer
{
   public:
	Placer(World& w, const Road& road, const CrossSection& cs, uint64_t seed, const char* purpose)
		: world(w), road(road), cs(cs), rng(Rng::stream(seed, purpose))
	{
	}
	World& world;
	const Road& road;
	CrossSection cs;
	Rng rng;
	TexturePool tex;

	/// Frame at arc length s, `lateral` to the left, on the road surface, x along the road, turned by yaw.
	Eigen::Isometry3d frameAt(double s, double lateral, double yaw = 0) const;
	/// True if a footprint sx x sy (centred on the frame) keeps `clear` metres from every part of the
	/// road's centre line and overlaps nothing placed before.
	bool fits(const Eigen::Isometry3d& f, double sx, double sy, double clear) const;
	void occupy(const Eigen::Isometry3d& f, double sx, double sy);
	bool occupied(const Eigen::Vector2d& p) const;
	template <class V>
	int pick(const V& ids)
	{
		return ids[rng.integer(0, static_cast<int>(ids.size()) - 1)];
	}

   private:
	std::unordered_set<int64_t> cells_;  // 0.5 m cells
	template <class F>
	bool forFootprint(const Eigen::Isometry3d& f, double sx, double sy, F&& fn) const;
};

void buildUrbanSide(Placer& p, double side, double s0, double s1, double skip_from, double skip_to);
/// Cars parked in the parking lane, and lamps and trees on the sidewalk, outside [skip_from, skip_to).
void streetParking(Placer& p, double side, double s0, double s1, double skip_from, double skip_to);
void streetLampsAndTrees(Placer& p, double side, double s0, double s1, double skip_from, double skip_to);
void buildResidentialSide(Placer& p, double side, double s0, double s1);
void buildCorridorWalls(Placer& p, double s0, double s1);
/// Trees along one side of the road: the first within `first` m of s0, then every gap[0]-gap[1] m,
/// off[0]-off[1] m beyond the clearance, trunks needing a free footprint, sizes size[0]-size[1].
struct TreeRow
{
	double first;
	double gap[2], off[2];
	double footprint;
	double size[2];
};
void plantTreeRow(Placer& p, double side, double s0, double s1, const TreeRow& row);
void buildTreesSide(Placer& p, double side, double s0, double s1);
void buildAvenueSide(Placer& p, double side, double s0, double s1);
void buildLoopSides(Placer& p, const std::vector<double>& turning_places, double park_from, double park_to);
void buildFacadeStreet(Placer& p, double period, double s0, double s1);
}  // namespace vlo::sim
