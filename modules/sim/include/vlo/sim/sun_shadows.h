#pragma once
// Strong sun through tree crowns: every surface the camera sees is lit or in a crown's hard, dappled
// shadow, as a road between trees on a clear day (KITTI raw 2011_09_26_0013 beyond frame 47). The
// render itself is an overcast day's (no shading); this scales each supersampled pixel by its light.
#include <vlo/sim/foliage.h>
#include <vlo/sim/renderer.h>

namespace vlo::sim
{
struct SunLight
{
	double elevation_deg = 40;  ///< above the horizon
	double azimuth_deg = 150;  ///< from the world's x axis, counter-clockwise
	double lit_gain = 1.45;  ///< sunlit surfaces: brighter than the overcast render, the brightest clip at 255
	double shade_gain = 0.4;  ///< in a crown's shadow: skylight only (sun : shade = 3.6 : 1)
	double gap_fraction = 0.3;  ///< leaf gaps (Foliage::shades): sunflecks inside the shadows
	Eigen::Vector3d toSun() const;
};

/// Scales the gray of every pixel with a surface (depth > 0) of the rendered camera tile by the light
/// at its world point: lit_gain, or shade_gain where a crown stands between it and the sun.
void applySunShadows(RenderedView& tile, const View& view, const Foliage& foliage, const SunLight& sun);
}  // namespace vlo::sim
