#include <vlo/io/undistort.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>

namespace vlo::io
{
struct ImageUndistorter::Maps
{
	PinholeCamera camera;  // the distorted camera the tables are for
	cv::Mat map1, map2;
};

ImageUndistorter::ImageUndistorter() = default;
ImageUndistorter::~ImageUndistorter() = default;

namespace
{
bool sameCamera(const PinholeCamera& a, const PinholeCamera& b)
{
	return a.fx == b.fx && a.fy == b.fy && a.cx == b.cx && a.cy == b.cy && a.width == b.width &&
		a.height == b.height && a.distortion == b.distortion && a.dist == b.dist;
}
}  // namespace

bool ImageUndistorter::apply(Frame& frame)
{
	PinholeCamera& cam = frame.rig.camera;
	if (!frame.has_image || !cam.distorted()) return false;
	if (!maps_ || !sameCamera(maps_->camera, cam))
	{
		maps_ = std::make_unique<Maps>();
		maps_->camera = cam;
		cv::Mat K;
		cv::eigen2cv(cam.K(), K);
		const cv::Size size(cam.width, cam.height);
		const auto& d = cam.dist;
		if (cam.distortion == mrpt::img::DistortionModel::kannala_brandt)
			cv::fisheye::initUndistortRectifyMap(K, cv::Vec4d(d[0], d[1], d[4], d[5]), cv::Matx33d::eye(), K, size,
				CV_16SC2, maps_->map1, maps_->map2);
		else  // plumb_bob: OpenCV's order is the same [k1 k2 p1 p2 k3 k4 k5 k6]
			cv::initUndistortRectifyMap(K, cv::Mat(std::vector<double>(d.begin(), d.end())), cv::Mat(), K, size,
				CV_16SC2, maps_->map1, maps_->map2);
	}
	cv::Mat out;
	cv::remap(frame.image.asCvMatRef(), out, maps_->map1, maps_->map2, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
	frame.image = mrpt::img::CImage(out, mrpt::img::SHALLOW_COPY);
	cam.distortion = mrpt::img::DistortionModel::none;
	cam.dist.fill(0.0);
	return true;
}
}  // namespace vlo::io
