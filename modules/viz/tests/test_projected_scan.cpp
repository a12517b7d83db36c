#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/viz/projected_scan.h>

#include "synthetic.h"
#include "test_util.h"

#include <opencv2/core.hpp>

using namespace vlo;
using namespace vlo::viz;

namespace
{
SensorRig smallRig()
{
	SensorRig rig = synth::kittiLikeRig();
	rig.camera = {500, 500, 320, 240, 640, 480};
	return rig;
}

mrpt::img::CImage grayImage(int w, int h)
{
	return mrpt::img::CImage(cv::Mat(h, w, CV_8UC1, cv::Scalar(128)), mrpt::img::DEEP_COPY);
}
}  // namespace

TEST(ProjectedScan, KnownPointLandsAtItsPixelInItsDepthColour)
{
	const SensorRig rig = smallRig();
	// LiDAR at (0, 0, 1.73), camera at (0.27, 0, 1.65) looking along vehicle x. A LiDAR point at
	// (10.27, 2, -0.5) is at camera (x, y, z) = (-2, 0.42, 10): pixel (220, 261), depth 10 m.
	const PointCloud scan{
		{10.27f, 2.f, -0.5f, 0.f}, {-5.f, 0.f, 0.f, 0.f} /*behind*/, {10.f, 30.f, 0.f, 0.f} /*outside*/};
	const auto proj = projectScan(scan, rig);
	ASSERT_EQ(proj.size(), 1u);
	EXPECT_NEAR(proj[0].px.x, 220, 1e-4);
	EXPECT_NEAR(proj[0].px.y, 261, 1e-4);
	EXPECT_NEAR(proj[0].depth, 10, 1e-5);

	ProjectedScanStyle style;
	style.max_depth = 20;
	style.point_radius = 2;
	const cv::Mat img = drawProjectedScan(grayImage(640, 480), scan, rig, {}, style);
	ASSERT_EQ(img.cols, 640);
	ASSERT_EQ(img.rows, 480 + kProjectedScanPanel);
	const Rgb expected = turbo(0.5);
	EXPECT_LT(test::colorDistance(img.at<cv::Vec3b>(261, 220), expected), 1.0);
	EXPECT_LT(test::colorDistance(img.at<cv::Vec3b>(262, 221), expected), 1.0);  // radius 2
	EXPECT_EQ(img.at<cv::Vec3b>(261, 225), cv::Vec3b(128, 128, 128));  // untouched image elsewhere
}

TEST(ProjectedScan, NearerPointsAreDrawnOnTop)
{
	const SensorRig rig = smallRig();
	// Two points on the same ray through the principal point, 10 m and 40 m deep.
	const PointCloud scan{{10.27f, 0.f, -0.08f, 0.f}, {40.27f, 0.f, -0.08f, 0.f}};
	ProjectedScanStyle style;
	style.max_depth = 50;
	const cv::Mat img = drawProjectedScan(grayImage(640, 480), scan, rig, {}, style);
	EXPECT_LT(test::colorDistance(img.at<cv::Vec3b>(240, 320), turbo(0.2)), 1.0);
}

TEST(ProjectedScan, OverlaysUseTheirColours)
{
	const SensorRig rig = smallRig();
	ImageOverlay ov;
	ov.points.push_back({{100, 100}, {255, 0, 255}, 4, true, 1});
	ov.segments.push_back({{300, 50}, {400, 50}, {0, 255, 0}, 1});
	ov.legend = {{"kept", {255, 0, 255}}, {"tracked", {0, 255, 0}}};
	const cv::Mat img = drawProjectedScan(grayImage(640, 480), {}, rig, ov);
	EXPECT_LT(test::colorDistance(img.at<cv::Vec3b>(100, 100), {255, 0, 255}), 1.0);
	EXPECT_LT(test::colorDistance(img.at<cv::Vec3b>(50, 350), {0, 255, 0}), 40.0);  // anti-aliased
}

TEST(ProjectedScan, ClearErrorsForInconsistentInput)
{
	SensorRig rig = smallRig();
	EXPECT_THROW(drawProjectedScan(grayImage(641, 480), {}, rig), InputError);
	rig.has_camera = false;
	EXPECT_THROW(drawProjectedScan(grayImage(640, 480), {}, rig), InputError);
}

namespace
{
/// The overlay legend's rings in reading order: each is on a 19x19 grey tile (128, 128, 128) below the image; the
/// colour is the ring's right-hand side, 6 pixels right of the tile's centre.
std::vector<cv::Vec3b> legendRings(const cv::Mat& img, int imageRows)
{
	std::vector<cv::Vec3b> rings;
	const cv::Vec3b tile(128, 128, 128);
	for (int y = imageRows; y + 18 < img.rows; ++y)
		for (int x = 0, run = 0; x < img.cols; ++x)
		{
			const bool grey = img.at<cv::Vec3b>(y, x) == tile;
			run = grey ? run + 1 : 0;
			// A tile's top row: 19 grey pixels in a row with none right above them.
			if (run == 19 && img.at<cv::Vec3b>(y - 1, x) != tile && (x + 1 == img.cols || img.at<cv::Vec3b>(y, x + 1) != tile))
				rings.push_back(img.at<cv::Vec3b>(y + 9, x - 9 + 6));
		}
	return rings;
}
}  // namespace

TEST(ProjectedScan, EveryLegendEntryIsShownWhateverTheImageWidth)
{
	// Six long entries, as the scale snapshots have on real data: beside the colour bar they fit only in a wide
	// image; narrower ones get rows of their own below it, and a taller panel.
	ImageOverlay ov;
	const std::vector<Rgb> colours{{0, 158, 115}, {0, 114, 178}, {213, 94, 0}, {204, 121, 167}, {240, 228, 66}, {255, 255, 255}};
	const char* names[] = {"inlier 251", "RANSAC outlier 104", "off epipolar line 215", "weak gradient 123",
		"not triangulated 175", "track lost 132"};
	for (int k = 0; k < 6; ++k) ov.legend.push_back({names[k], colours[k]});
	for (int w : {2400, 1241, 1226, 640, 320})
	{
		SensorRig rig = smallRig();
		rig.camera.width = w, rig.camera.cx = w / 2.0;
		const cv::Mat img = drawProjectedScan(grayImage(w, 480), {}, rig, ov);
		EXPECT_GE(img.rows, 480 + kProjectedScanPanel);
		const auto rings = legendRings(img, 480);
		ASSERT_EQ(rings.size(), ov.legend.size()) << "width " << w;
		for (size_t k = 0; k < rings.size(); ++k)
			EXPECT_LT(test::colorDistance(rings[k], colours[k]), 40) << "width " << w << ": " << names[k];
		if (w == 2400)
		{
			EXPECT_EQ(img.rows, 480 + kProjectedScanPanel);  // one row beside the colour bar
		}
		if (w == 320)
		{
			EXPECT_GT(img.rows, 480 + kProjectedScanPanel + 24 * 3);  // a row per entry or so
		}
	}
}
