#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/viz/map3d.h>

#include "../src/gl_render.h"
#include "../src/map3d_view.h"
#include "../src/view_fit.h"
#include "synthetic.h"
#include "test_util.h"

#include <opencv2/imgcodecs.hpp>

using namespace vlo;
using namespace vlo::viz;

TEST(Map3D, FittedViewKeepsEveryPointInsideTheContentRectangle)
{
	std::vector<Eigen::Vector3d> pts;
	for (int k = 0; k < 200; ++k) pts.emplace_back(5.0 * k, 50 * std::sin(k * 0.05), 0.1 * k);
	const cv::Rect content(20, 40, 760, 500);
	const ViewCamera cam = fitView(pts, acrossAzimuth(pts), 0.8, 0.6, content, 800, 600);
	double u0 = 1e9, u1 = -1e9, v0 = 1e9, v1 = -1e9;
	for (const auto& p : pts)
	{
		const auto q = cam.project(p);
		ASSERT_TRUE(q);
		u0 = std::min(u0, q->x), u1 = std::max(u1, q->x), v0 = std::min(v0, q->y), v1 = std::max(v1, q->y);
	}
	EXPECT_GE(u0, content.x - 0.5);
	EXPECT_LE(u1, content.br().x + 0.5);
	EXPECT_GE(v0, content.y - 0.5);
	EXPECT_LE(v1, content.br().y + 0.5);
	// Tight in at least one direction: the view is as close as it can be.
	EXPECT_TRUE(u1 - u0 > 0.98 * content.width || v1 - v0 > 0.98 * content.height);
}

TEST(Map3D, OpenGlRenderAgreesWithTheOverlayProjection)
{
	// Large points at known places; the rendered colour must be where ViewCamera::project says,
	// including with a principal point far from the image centre.
	const std::vector<Eigen::Vector3d> where{{0, 0, 0}, {40, 0, 0}, {0, 30, 0}, {40, 30, 10}, {20, 15, 5}};
	const Rgb colors[] = {{255, 0, 0}, {0, 160, 0}, {0, 0, 255}, {200, 0, 200}, {0, 0, 0}};
	GlPoints pts;
	for (size_t k = 0; k < where.size(); ++k) pts.push_back({where[k].cast<float>(), colors[k]});
	const ViewCamera cam = fitView(where, 0.3, 0.7, 0.6, cv::Rect(100, 50, 400, 300), 701, 501);
	const cv::Mat img = renderPoints(pts, cam, 9);
	ASSERT_EQ(img.cols, 701);  // odd width: exercises the pack-alignment workaround
	ASSERT_EQ(img.rows, 501);
	for (size_t k = 0; k < where.size(); ++k)
		EXPECT_TRUE(test::colorNear(img, *cam.project(where[k]), colors[k], 1, 10)) << k;
	EXPECT_TRUE(test::colorNear(img, {650, 450}, {255, 255, 255}, 0, 1));  // white background
}

TEST(Map3D, DrawsMapAndTrajectoryAndWritesPng)
{
	PointCloud map;
	for (int x = 0; x < 100; ++x)
		for (int y = -10; y <= 10; ++y) map.push_back({float(x), float(y), float(-1.7 + 0.05 * y), 0});
	Trajectory traj;
	for (int k = 0; k < 100; ++k)
	{
		StampedPose p;
		p.t = k;
		p.pose.translation() = Eigen::Vector3d(k, 0, 0);
		traj.push_back(p);
	}
	Map3DStyle style;
	style.width = 800, style.height = 500;
	const std::string png = ::testing::TempDir() + "vlo_map3d.png";
	renderMap3D(map, {{"est", traj, Rgb{213, 94, 0}}}, &traj, png, style);
	const cv::Mat img = cv::imread(png);
	ASSERT_EQ(img.cols, 800);
	ASSERT_EQ(img.rows, 500);
	long orange = 0;
	for (int y = 0; y < img.rows; ++y)
		for (int x = 0; x < img.cols; ++x) orange += test::colorDistance(img.at<cv::Vec3b>(y, x), {213, 94, 0}) < 20;
	EXPECT_GT(orange, 300);  // a thick line across the view
	EXPECT_THROW(drawMap3D({}, {}, nullptr), InputError);
}

TEST(Map3D, LongDriveIsFramedWholeWithTheMainResultOnTop)
{
	// A 1.2 km drive whose map covers only its last 150 m (a local map): the view still frames every pose. The VO
	// (second) starts 100 poses late on the same path as the main result (first) and the ground truth; the main result
	// must be drawn above both, its end square too.
	const Trajectory gt = synth::curvedDrive(1200);
	ASSERT_GT(gt.size(), 300u);
	PointCloud map;
	for (size_t k = gt.size() - 150; k < gt.size(); ++k)
		for (double side : {-8.0, 8.0})
			for (double z : {-1.7, 0.0, 2.0})
			{
				const Eigen::Vector3d p = gt[k].pose * Eigen::Vector3d(0, side, z);
				map.push_back({float(p.x()), float(p.y()), float(p.z()), 0});
			}
	const Rgb main{0, 114, 178}, vo{213, 94, 0};
	const std::vector<NamedTrajectory> trajs{{"VLO", gt, main}, {"VO", Trajectory(gt.begin() + 100, gt.end()), vo}};
	Map3DStyle style;
	style.width = 1000, style.height = 700;
	const cv::Mat img = drawMap3D(map, trajs, &gt, style);
	const ViewCamera cam = map3DView(map, trajs, &gt, style);
	const cv::Rect view(0, 0, style.width, style.height - 64);  // above the colour bar's strip
	for (const auto& p : gt)
	{
		const auto q = cam.project(p.pose.translation());
		ASSERT_TRUE(q);
		EXPECT_TRUE(view.contains(cv::Point(cvRound(q->x), cvRound(q->y)))) << "pose at t = " << p.t << " is out of the view";
	}
	const cv::Point2d start = *cam.project(gt.front().pose.translation()), end = *cam.project(gt.back().pose.translation()),
					  voStart = *cam.project(gt[100].pose.translation());
	EXPECT_TRUE(test::colorNear(img, start + cv::Point2d(7, 0), {40, 40, 40}, 1, 10));  // the drive's start ring
	EXPECT_TRUE(test::colorNear(img, voStart, vo, 1, 10));  // the VO's diamond
	EXPECT_TRUE(test::colorNear(img, end, main, 1, 10));  // ends: the main result's square drawn last
	// Between the markers the shared path is the main result's colour, not the VO's.
	int onTop = 0, checked = 0;
	for (size_t k = 130; k + 30 < gt.size(); k += 25, ++checked)
		onTop += test::colorNear(img, *cam.project(gt[k].pose.translation()), main, 0, 10);
	EXPECT_GT(onTop, 0.9 * checked);
	// The legend explains the diamond.
	const cv::Rect legend = test::findLegend(img);
	ASSERT_FALSE(legend.empty());
	EXPECT_EQ(legend.height, 2 * 10 + 24 * 6 - 6);  // ground truth, VLO, VO, start of the drive, of a later path, end
}
