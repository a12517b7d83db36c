#include <vlo/sim/sun_shadows.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
Eigen::Vector3d SunLight::toSun() const
{
	const double e = elevation_deg * M_PI / 180, a = azimuth_deg * M_PI / 180;
	return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

void applySunShadows(RenderedView& tile, const View& view, const Foliage& foliage, const SunLight& sun)
{
	const Eigen::Vector3d toSun = sun.toSun();
	const PinholeCamera& K = view.K;
	for (int r = 0; r < tile.height; ++r)
		for (int c = 0; c < tile.width; ++c)
		{
			const std::size_t i = static_cast<std::size_t>(r) * tile.width + c;
			const double z = tile.depth[i];
			if (z <= 0) continue;  // sky
			const Eigen::Vector3d cam(z * (c - K.cx) / K.fx, z * (r - K.cy) / K.fy, z);
			const bool shaded = foliage.shades(view.world_T_cam * cam, toSun, sun.gap_fraction);
			const double g = tile.gray[i] * (shaded ? sun.shade_gain : sun.lit_gain);
			tile.gray[i] = static_cast<uint8_t>(std::clamp(std::lround(g), 0L, 255L));
		}
}
}  // namespace vlo::sim
