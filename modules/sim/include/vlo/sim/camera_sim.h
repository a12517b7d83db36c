#pragma once
// The camera: rendered at twice the resolution and averaged 2x2 (anti-aliasing edges and textures,
// which MRPT draws without mipmaps), then, for a camera with lens distortion, warped through the lens
// (the pinhole picture sampled where each distorted pixel looks), then mild Gaussian noise, or a real
// camera's blur, exposure and noise (camera_errors.h).
#include <vlo/sim/realism.h>
#include <vlo/sim/renderer.h>

#include <mrpt/img/CImage.h>

#include <memory>

namespace vlo::sim
{
class Rng;

class CameraSim
{
   public:
	/// `K` may carry a lens distortion (plumb_bob or kannala_brandt): the images come out distorted.
	explicit CameraSim(const PinholeCamera& K, double zfar = 160.0);
	~CameraSim();
	std::pair<int, int> tileSize() const;
	/// The supersampled view for a camera (optical frame) pose in the world.
	View view(const Eigen::Isometry3d& world_T_cam) const;
	/// Output image from the rendered tile: 2x2 mean, plus noise of `sigma` gray levels; or, with
	/// `realism`, a real camera's blur, exposure `gain` and noise instead (camera_errors.h).
	mrpt::img::CImage image(const RenderedView& tile, double sigma, Rng& rng, const CameraRealism* realism = nullptr, double gain = 1) const;
	/// Rendered z-depth at output pixel coordinates (u, v) (OpenCV convention) of a camera without
	/// distortion, 0 if none.
	static float depthAt(const RenderedView& tile, double u, double v);

   private:
	const PinholeCamera& pinhole() const;  ///< the camera rendered (K_, widened for a lens)

	PinholeCamera K_;
	double zfar_;
	struct Lens;  // remap tables from distorted output pixels to pinhole pixels
	std::unique_ptr<Lens> lens_;
};
}  // namespace vlo::sim
