#pragma once
// Headless rendering of several pinhole views per call into tiles of ONE offscreen framebuffer
// (mrpt::opengl::CFBORender + EGL): the camera and the LiDAR's depth views share one renderer, which
// the field notes require (a scene rendered by one CFBORender cannot be rendered by another).
#include <vlo/core/frame.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <vector>

namespace mrpt::opengl
{
class COpenGLScene;
class CRenderizable;
}  // namespace mrpt::opengl

namespace vlo::sim
{
/// One view. Intrinsics use the OpenCV convention (the centre of pixel (c, r) is at (c, r)); the
/// renderer converts to OpenGL's (centres at +0.5) so that images agree with K to the sub-pixel.
struct View
{
	Eigen::Isometry3d world_T_cam = Eigen::Isometry3d::Identity();  ///< optical frame: z fwd, x right, y down
	PinholeCamera K;
	double znear = 1.0, zfar = 150.0;
	bool moving = true;  ///< draw the moving objects passed to Renderer::render (the LiDAR ray-casts them instead)
};

struct RenderedView
{
	int width = 0, height = 0;
	std::vector<float> depth;  ///< row-major, top row first; z along the optical axis (m), 0 = no surface
	std::vector<uint8_t> gray;  ///< same layout, when requested
	float depthAt(int r, int c) const { return depth[static_cast<std::size_t>(r) * width + c]; }
};

/// Only one Renderer may exist at a time in a process (MRPT's EGL display is shared).
class Renderer
{
   public:
	/// Tiles of these sizes (w, h) are packed in rows into one framebuffer, fixed for the lifetime.
	explicit Renderer(const std::vector<std::pair<int, int>>& tile_sizes);
	~Renderer();
	Renderer(const Renderer&) = delete;
	Renderer& operator=(const Renderer&) = delete;

	/// Renders views[i] into tile i (sizes must match), then reads back depth, and gray if asked.
	/// `moving` (part of the scene, may be null) is drawn only in the views that ask for it.
	void render(mrpt::opengl::COpenGLScene& scene, const std::vector<View>& views, std::vector<RenderedView>& out, bool gray,
		mrpt::opengl::CRenderizable* moving = nullptr);

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};
}  // namespace vlo::sim
