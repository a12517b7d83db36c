#include <vlo/core/se3.h>
#include <vlo/sim/renderer.h>

#include <mrpt/img/TCamera.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>

#include <GL/gl.h>

#include <algorithm>
#include <stdexcept>

namespace vlo::sim
{
namespace
{
/// CFBORender owns the EGL context and the framebuffer; this subclass only needs access to the
/// framebuffer to draw several viewports, each with its own camera, before reading back.
class TiledFbo : public mrpt::opengl::CFBORender
{
   public:
	TiledFbo(int w, int h) : CFBORender(Parameters(w, h))
	{
		// Rows of odd widths come out sheared without this (field notes).
		glPixelStorei(GL_PACK_ALIGNMENT, 1);
	}
	mrpt::opengl::COpenGLFramebuffer& fb() { return m_fb; }
};

struct Tile
{
	int x, y, w, h;  // top-left origin
};
}  // namespace

struct Renderer::Impl
{
	std::vector<Tile> tiles;
	int width = 0, height = 0;
	std::unique_ptr<TiledFbo> fbo;
	std::vector<uint8_t> rgb;
	std::vector<float> zbuf;
	std::vector<std::pair<double, double>> clip;  // per tile: near, far used by the last render
};

namespace
{
int g_alive = 0;  // renderers alive in this process
}

Renderer::Renderer(const std::vector<std::pair<int, int>>& sizes) : impl_(std::make_unique<Impl>())
{
	// Destroying a CFBORender terminates the EGL display that every renderer shares, so two alive at
	// once end in a crash: refuse the second one clearly.
	if (g_alive > 0) throw std::logic_error("vlo::sim::Renderer: only one renderer (simulator) may exist at a time");
	// Shelf packing: rows no wider than the widest tile or 2560 px.
	int maxw = 2560;
	for (const auto& s : sizes) maxw = std::max(maxw, s.first);
	int x = 0, y = 0, rowh = 0;
	for (const auto& s : sizes)
	{
		if (x + s.first > maxw) x = 0, y += rowh, rowh = 0;
		impl_->tiles.push_back({x, y, s.first, s.second});
		x += s.first, rowh = std::max(rowh, s.second);
		impl_->width = std::max(impl_->width, x);
	}
	impl_->height = y + rowh;
	impl_->fbo = std::make_unique<TiledFbo>(impl_->width, impl_->height);
	++g_alive;
	impl_->clip.resize(sizes.size());
}

Renderer::~Renderer() { --g_alive; }

void Renderer::render(mrpt::opengl::COpenGLScene& scene, const std::vector<View>& views, std::vector<RenderedView>& out, bool gray,
	mrpt::opengl::CRenderizable* moving)
{
	auto& d = *impl_;
	if (views.size() != d.tiles.size()) throw std::logic_error("Renderer::render: one view per tile expected");
	out.resize(views.size());
	auto vp = scene.getViewport("main");
	const auto old = d.fbo->fb().bind();
	for (std::size_t i = 0; i < views.size(); ++i)
	{
		const Tile& t = d.tiles[i];
		const View& v = views[i];
		if (v.K.width != t.w || v.K.height != t.h) throw std::logic_error("Renderer::render: view size mismatch");
		mrpt::img::TCamera tc;
		tc.ncols = t.w, tc.nrows = t.h;
		tc.setIntrinsicParamsFromValues(v.K.fx, v.K.fy, v.K.cx + 0.5, v.K.cy + 0.5);  // OpenCV -> OpenGL centres
		mrpt::opengl::CCamera cam;
		cam.setProjectiveFromPinhole(tc);
		cam.set6DOFMode(true);
		cam.setPose(toCPose3D(v.world_T_cam));
		// Pixel values (> 1) place the viewport; OpenGL counts rows from the bottom.
		vp->setViewportPosition(t.x, d.height - t.y - t.h, t.w, t.h);
		vp->setViewportClipDistances(static_cast<float>(v.znear), static_cast<float>(v.zfar));
		if (moving) moving->setVisibility(v.moving);
		glEnable(GL_DEPTH_TEST);
		vp->render(d.width, d.height, 0, 0, &cam);
		// The clip distances MRPT actually used (as CFBORender does) define the depth mapping.
		const auto mats = vp->getRenderMatrices();
		d.clip[i] = {mats.getLastClipZNear(), mats.getLastClipZFar()};
	}
	for (std::size_t i = 0; i < views.size(); ++i)
	{
		const Tile& t = d.tiles[i];
		RenderedView& r = out[i];
		r.width = t.w, r.height = t.h;
		const std::size_t n = static_cast<std::size_t>(t.w) * t.h;
		d.zbuf.resize(n);
		glReadPixels(t.x, d.height - t.y - t.h, t.w, t.h, GL_DEPTH_COMPONENT, GL_FLOAT, d.zbuf.data());
		r.depth.resize(n);
		const double zn = d.clip[i].first, zf = d.clip[i].second;
		for (int row = 0; row < t.h; ++row)
		{
			const float* src = &d.zbuf[static_cast<std::size_t>(t.h - 1 - row) * t.w];  // bottom-up
			float* dst = &r.depth[static_cast<std::size_t>(row) * t.w];
			for (int c = 0; c < t.w; ++c)
			{
				const double z = src[c];
				dst[c] = z >= 1.0 ? 0.f : static_cast<float>(2.0 * zn * zf / (zf + zn - (2.0 * z - 1.0) * (zf - zn)));
			}
		}
		if (!gray) continue;
		d.rgb.resize(3 * n);
		glReadPixels(t.x, d.height - t.y - t.h, t.w, t.h, GL_RGB, GL_UNSIGNED_BYTE, d.rgb.data());
		r.gray.resize(n);
		for (int row = 0; row < t.h; ++row)
		{
			const uint8_t* src = &d.rgb[3 * static_cast<std::size_t>(t.h - 1 - row) * t.w];
			uint8_t* dst = &r.gray[static_cast<std::size_t>(row) * t.w];
			for (int c = 0; c < t.w; ++c) dst[c] = static_cast<uint8_t>((src[3 * c] + src[3 * c + 1] + src[3 * c + 2] + 1) / 3);
		}
	}
	mrpt::opengl::COpenGLFramebuffer::Bind(old);
}
}  // namespace vlo::sim
