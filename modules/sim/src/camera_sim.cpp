#include <vlo/sim/camera_sim.h>
#include <vlo/sim/rng.h>

#include <algorithm>
#include <cmath>

namespace vlo::sim
{
CameraSim::CameraSim(const PinholeCamera& K, double zfar) : K_(K), zfar_(zfar) {}

View CameraSim::view(const Eigen::Isometry3d& world_T_cam) const
{
	// Output pixel c covers supersampled pixels 2c and 2c+1, whose centres are at 2c and 2c+1 in the
	// supersampled image: output coordinate u maps to 2u + 0.5.
	View v;
	v.world_T_cam = world_T_cam;
	v.K = K_;
	v.K.fx = 2 * K_.fx, v.K.fy = 2 * K_.fy;
	v.K.cx = 2 * K_.cx + 0.5, v.K.cy = 2 * K_.cy + 0.5;
	v.K.width = 2 * K_.width, v.K.height = 2 * K_.height;
	v.znear = 1.0, v.zfar = zfar_;
	return v;
}

mrpt::img::CImage CameraSim::image(const RenderedView& t, double sigma, Rng& rng) const
{
	mrpt::img::CImage img(K_.width, K_.height, mrpt::img::CH_GRAY);
	for (int r = 0; r < K_.height; ++r)
	{
		const uint8_t* a = &t.gray[static_cast<std::size_t>(2 * r) * t.width];
		const uint8_t* b = a + t.width;
		auto* out = img.ptrLine<uint8_t>(r);
		for (int c = 0; c < K_.width; ++c)
		{
			const double mean = (a[2 * c] + a[2 * c + 1] + b[2 * c] + b[2 * c + 1]) / 4.0;
			const double v = mean + (sigma > 0 ? sigma * rng.normal() : 0.0);
			out[c] = static_cast<uint8_t>(std::clamp(std::lround(v), 0L, 255L));
		}
	}
	return img;
}

float CameraSim::depthAt(const RenderedView& t, double u, double v)
{
	const int c = static_cast<int>(std::lround(2 * u + 0.5)), r = static_cast<int>(std::lround(2 * v + 0.5));
	if (c < 0 || r < 0 || c >= t.width || r >= t.height) return 0.f;
	return t.depthAt(r, c);
}
}  // namespace vlo::sim
