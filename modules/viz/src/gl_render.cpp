#include "gl_render.h"

#include <vlo/core/se3.h>

#include <mrpt/img/TCamera.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloudColoured.h>

#include <GL/gl.h>
#include <opencv2/imgproc.hpp>

namespace vlo::viz
{
cv::Mat renderPoints(const GlPoints& pts, const ViewCamera& cam, float pointSize)
{
	using namespace mrpt::opengl;
	COpenGLScene scene;
	scene.getViewport()->setCustomBackgroundColor({1.f, 1.f, 1.f, 1.f});
	scene.getViewport()->setViewportClipDistances(float(cam.near), float(cam.far));
	auto cloud = CPointCloudColoured::Create();
	cloud->reserve(pts.size());
	for (const auto& q : pts) cloud->push_back(q.p.x(), q.p.y(), q.p.z(), q.c.r / 255.f, q.c.g / 255.f, q.c.b / 255.f);
	cloud->setPointSize(pointSize);
	scene.insert(cloud);

	// A fresh renderer per scene: a scene once rendered by one CFBORender cannot be rendered by another.
	CFBORender fbo(CFBORender::Parameters(cam.width, cam.height));
	// Rows are read back tightly packed; the default alignment of 4 shears widths where 3*W % 4 != 0.
	glPixelStorei(GL_PACK_ALIGNMENT, 1);
	mrpt::img::TCamera K;
	K.ncols = cam.width, K.nrows = cam.height;
	K.setIntrinsicParamsFromValues(cam.f, cam.f, cam.cx, cam.cy);
	CCamera& c = fbo.getCamera(scene);
	c.setProjectiveFromPinhole(K);
	c.set6DOFMode(true);
	c.setPose(toCPose3D(cam.world_T_cam));

	mrpt::img::CImage rgb;
	fbo.render_RGB(scene, rgb);
	return rgb.asCvMatRef().clone();
}
}  // namespace vlo::viz
