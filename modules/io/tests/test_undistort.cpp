// Undistortion of whole images: a dot drawn where the lens puts a 3D point ends up where the ideal
// pinhole camera (same K) projects it, for both lens models.
#include "io_test_util.h"

#include <vlo/io/undistort.h>

#include <opencv2/calib3d.hpp>

#include <cmath>

using namespace vlo;
using namespace vlo::io;

namespace
{
struct Dot
{
	cv::Point2d distorted, pinhole;
};

/// Frame with Gaussian dots (sigma 1.5 px) at the distorted projections of a grid of 3D points.
Frame dottedFrame(const PinholeCamera& cam, std::vector<Dot>& dots)
{
	const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
	std::vector<cv::Point3d> X;
	for (double x = -0.5; x <= 0.51; x += 0.25)
		for (double y = -0.3; y <= 0.31; y += 0.15) X.push_back({x, y, 1.0});
	std::vector<cv::Point2d> d, p;
	const auto& c = cam.dist;
	if (cam.distortion == mrpt::img::DistortionModel::kannala_brandt)
		cv::fisheye::projectPoints(X, d, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, cv::Vec4d(c[0], c[1], c[4], c[5]));
	else
		cv::projectPoints(X, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, std::vector<double>(c.begin(), c.end()), d);
	cv::projectPoints(X, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, cv::noArray(), p);
	cv::Mat img(cam.height, cam.width, CV_8UC1, cv::Scalar(0));
	for (std::size_t i = 0; i < X.size(); ++i)
	{
		dots.push_back({d[i], p[i]});
		for (int r = int(d[i].y) - 6; r <= int(d[i].y) + 6; ++r)
			for (int col = int(d[i].x) - 6; col <= int(d[i].x) + 6; ++col)
			{
				const double e = (std::pow(col - d[i].x, 2) + std::pow(r - d[i].y, 2)) / (2 * 1.5 * 1.5);
				img.at<uint8_t>(r, col) = cv::saturate_cast<uint8_t>(img.at<uint8_t>(r, col) + 250 * std::exp(-e));
			}
	}
	Frame f;
	f.has_image = true;
	f.image = mrpt::img::CImage(img, mrpt::img::DEEP_COPY);
	f.rig.has_camera = true;
	f.rig.camera = cam;
	return f;
}

/// Intensity-weighted centroid of the image in a window around `at`.
cv::Point2d centroid(const mrpt::img::CImage& image, cv::Point2d at)
{
	const cv::Mat& m = const_cast<mrpt::img::CImage&>(image).asCvMatRef();
	double sw = 0, sx = 0, sy = 0;
	for (int r = int(std::lround(at.y)) - 5; r <= int(std::lround(at.y)) + 5; ++r)
		for (int c = int(std::lround(at.x)) - 5; c <= int(std::lround(at.x)) + 5; ++c)
		{
			const double w = m.at<uint8_t>(r, c);
			sw += w, sx += w * c, sy += w * r;
		}
	return {sx / sw, sy / sw};
}

void expectDotsMoveToThePinholeProjection(const PinholeCamera& cam)
{
	std::vector<Dot> dots;
	Frame f = dottedFrame(cam, dots);
	ImageUndistorter undistorter;
	ASSERT_TRUE(undistorter.apply(f));
	EXPECT_FALSE(f.rig.camera.distorted());
	EXPECT_EQ(f.rig.camera.fx, cam.fx);
	ASSERT_EQ(int(f.image.getWidth()), cam.width);
	double worst_before = 0, worst_after = 0;
	for (const auto& d : dots)
	{
		worst_before = std::max(worst_before, cv::norm(d.distorted - d.pinhole));
		worst_after = std::max(worst_after, cv::norm(centroid(f.image, d.pinhole) - d.pinhole));
	}
	EXPECT_GT(worst_before, 5.0);  // the lens moves the outer dots by pixels
	EXPECT_LT(worst_after, 0.15);
	EXPECT_FALSE(undistorter.apply(f));  // a pinhole frame is left alone
}

PinholeCamera camera()
{
	PinholeCamera c;
	c.fx = 600, c.fy = 610, c.cx = 322.5, c.cy = 241.0, c.width = 640, c.height = 480;
	return c;
}
}  // namespace

TEST(ImageUndistorter, PlumbBobRationalModel)
{
	PinholeCamera c = camera();
	c.distortion = mrpt::img::DistortionModel::plumb_bob;
	c.dist = {-0.25, 0.08, 0.001, -0.0015, -0.01, 0.02, -0.005, 0.001};
	expectDotsMoveToThePinholeProjection(c);
}

TEST(ImageUndistorter, EquidistantFisheye)
{
	PinholeCamera c = camera();
	c.distortion = mrpt::img::DistortionModel::kannala_brandt;
	c.dist = {-0.05, 0.01, 0, 0, -0.004, 0.001, 0, 0};
	expectDotsMoveToThePinholeProjection(c);
}
