#pragma once
// The camera: rendered at twice the resolution and averaged 2x2 (anti-aliasing edges and textures,
// which MRPT draws without mipmaps), then mild Gaussian noise.
#include <vlo/sim/renderer.h>

#include <mrpt/img/CImage.h>

namespace vlo::sim
{
class Rng;

class CameraSim
{
   public:
	explicit CameraSim(const PinholeCamera& K, double zfar = 160.0);
	std::pair<int, int> tileSize() const { return {2 * K_.width, 2 * K_.height}; }
	/// The supersampled view for a camera (optical frame) pose in the world.
	View view(const Eigen::Isometry3d& world_T_cam) const;
	/// Output image from the rendered tile: 2x2 mean, plus noise of `sigma` gray levels.
	mrpt::img::CImage image(const RenderedView& tile, double sigma, Rng& rng) const;
	/// Rendered z-depth at output pixel coordinates (u, v) (OpenCV convention), 0 if none.
	static float depthAt(const RenderedView& tile, double u, double v);

   private:
	PinholeCamera K_;
	double zfar_;
};
}  // namespace vlo::sim
