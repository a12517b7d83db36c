#pragma once
// Procedural, seeded gray textures with physical size. They are made for the estimators: plenty of
// corners (ORB/FAST) and gradients (Lucas-Kanade), little fine periodic detail (no mipmaps in MRPT,
// so fine patterns would alias and flicker at a distance).
#include <mrpt/img/CImage.h>

#include <cstdint>

namespace vlo::sim
{
/// An image that spans width_m x height_m metres of surface before it repeats.
struct Texture
{
	mrpt::img::CImage image;
	double width_m = 1, height_m = 1;
};

/// Road cross-section used by the road texture (metres from the centre line).
struct RoadMarkings
{
	double half_width = 5.7;  ///< asphalt edge
	double lane = 3.5;  ///< driving lane edge (solid line when parking lanes exist)
	bool center_line = true;
	bool parking_bays = true;  ///< short lines between lane edge and asphalt edge
};

/// Asphalt with markings; u runs along the road (24 m per repeat), v across it (0 = right edge).
Texture roadTexture(const RoadMarkings& m, uint64_t seed);
Texture sidewalkTexture(uint64_t seed);
Texture curbTexture(uint64_t seed);
Texture grassTexture(uint64_t seed, float base);
Texture gravelTexture(uint64_t seed);
/// Building facade, 16 m wide and 24 m tall; v = 0 at street level.
Texture facadeTexture(uint64_t seed);
Texture roofTexture(uint64_t seed);
/// Car body (lower part, with wheels) and cabin (windows), 4.5 m long.
Texture carBodyTexture(uint64_t seed);
Texture carCabinTexture(uint64_t seed);
Texture barkTexture(uint64_t seed);
Texture foliageTexture(uint64_t seed);
Texture poleTexture(uint64_t seed);
Texture signTexture(uint64_t seed);
Texture gardenWallTexture(uint64_t seed);
/// Corridor wall: posters, panels, graffiti strokes; 32 m x 8 m, no periodic structure inside.
Texture muralTexture(uint64_t seed);
}  // namespace vlo::sim
