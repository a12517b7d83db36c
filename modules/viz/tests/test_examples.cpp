// Realistic examples for reviewers: writes <build>/viz_examples/*.png, prints render times, and checks on the
// written file what each picture must show (where the data lands, in which colour, the legend, the size).
#include <gtest/gtest.h>
#include <vlo/io/pcd.h>
#include <vlo/viz/map3d.h>
#include <vlo/viz/projected_scan.h>
#include <vlo/viz/series.h>
#include <vlo/viz/topdown.h>

#include "../src/map3d_view.h"
#include "synthetic.h"
#include "test_util.h"

#include <mrpt/system/filesystem.h>
#include <opencv2/imgcodecs.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <random>

using namespace vlo;
using namespace vlo::viz;

namespace
{
const std::string kOut = std::string(VLO_BIN_DIR) + "/../viz_examples/";
const Rgb kStartInk{40, 40, 40}, kEndFill{200, 200, 200};  // legend swatches of the start and end markers

/// Runs `render`, prints how long it took, and reads back the PNG it wrote.
template <typename F>
cv::Mat renderAndRead(const std::string& name, F&& render)
{
	const auto t0 = std::chrono::steady_clock::now();
	render(kOut + name);
	std::cout << name << ": " << std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()
			  << " ms\n";
	return cv::imread(kOut + name, cv::IMREAD_COLOR);
}

struct Example : ::testing::Test
{
	static void SetUpTestSuite() { mrpt::system::createDirectory(kOut); }
};

struct Line
{
	std::vector<cv::Point2d> px;
	Rgb color;
};

/// Every `stride`-th vertex of each line has the line's colour, unless it is under the legend, a start or end
/// marker (of any line), or a line drawn later within `covered` pixels. Returns how many vertices were checked per line.
std::vector<int> expectLinesVisible(const cv::Mat& img, const std::vector<Line>& lines, const cv::Rect& legend,
	size_t stride, double covered)
{
	std::vector<int> checked(lines.size(), 0);
	const cv::Rect nearLegend(legend.x - 4, legend.y - 4, legend.width + 8, legend.height + 8);
	for (size_t i = 0; i < lines.size(); ++i)
		for (size_t k = 0; k < lines[i].px.size(); k += stride)
		{
			const cv::Point2d p = lines[i].px[k];
			bool hidden = nearLegend.contains(cv::Point(int(p.x), int(p.y)));
			for (const auto& l : lines) hidden |= cv::norm(p - l.px.front()) < 14 || cv::norm(p - l.px.back()) < 14;
			for (size_t j = i + 1; j < lines.size(); ++j) hidden |= test::distanceToPolyline(p, lines[j].px) < covered;
			if (hidden) continue;
			EXPECT_TRUE(test::colorNear(img, p, lines[i].color, 1)) << "line " << i << " vertex " << k << " at " << p;
			++checked[i];
		}
	return checked;
}
}  // namespace

TEST_F(Example, TopDownOfAOneKilometreDrive)
{
	const Trajectory gt = synth::curvedDrive(1000);
	const std::vector<NamedTrajectory> trajs{{"vlo (VO + LiDAR)", synth::driftingEstimate(gt, 0.01, 2e-5, 1, 1), {}},
		{"VO only", synth::driftingEstimate(gt, -0.12, 1.2e-4, 2, 2), {}}};
	TopDownStyle style;
	style.width = 1200, style.height = 900;
	style.title = "Trajectories, top-down (synthetic urban drive)";
	const cv::Mat img =
		renderAndRead("topdown.png", [&](const std::string& png) { renderTopDown(trajs, &gt, png, style); });
	ASSERT_EQ(img.cols, 1200);
	ASSERT_EQ(img.rows, 900);

	// Legend rows: ground truth, the estimates in their palette colours, start ring, end square.
	const cv::Rect legend = test::findLegend(img);
	ASSERT_FALSE(legend.empty());
	const Rgb rows[] = {kGroundTruthColor, paletteColor(0), paletteColor(1), kStartInk, kEndFill};
	for (int i = 0; i < 5; ++i) EXPECT_TRUE(test::colorNear(img, test::legendSwatch(legend, i), rows[i], 7)) << i;

	// Each path where the plot mapping puts its poses, in drawing order: ground truth, then the estimates
	// with the first listed (the main result) on top.
	const PlotArea a = topDownArea(trajs, &gt, style);
	auto pixels = [&](const Trajectory& t) {
		std::vector<cv::Point2d> px;
		for (const auto& p : t) px.push_back(a.toPixel(p.pose.translation().x(), p.pose.translation().y()));
		return px;
	};
	const std::vector<Line> lines{{pixels(gt), kGroundTruthColor}, {pixels(trajs[1].traj), paletteColor(1)},
		{pixels(trajs[0].traj), paletteColor(0)}};
	const auto checked = expectLinesVisible(img, lines, legend, 20, 3);
	for (size_t i = 0; i < lines.size(); ++i) EXPECT_GE(checked[i], 5) << "line " << i << " hidden almost everywhere";
	// End markers: a square of each estimate's colour on its last pose.
	EXPECT_TRUE(test::colorNear(img, lines[1].px.back(), paletteColor(1), 0, 1));
	EXPECT_TRUE(test::colorNear(img, lines[2].px.back(), paletteColor(0), 0, 1));
}

TEST_F(Example, Map3DOfAStreet)
{
	const Trajectory gt = synth::curvedDrive(1000);
	const PointCloud map = synth::streetMap(gt, 3);
	io::writePcd(kOut + "street_map.pcd", map);
	const std::vector<NamedTrajectory> trajs{{"vlo (VO + LiDAR)", synth::driftingEstimate(gt, 0.01, 2e-5, 1, 1), {}}};
	Map3DStyle style;
	style.width = 1500, style.height = 900;
	style.title = "Map and trajectory (synthetic street)";
	const cv::Mat img =
		renderAndRead("map3d.png", [&](const std::string& png) { renderMap3D(map, trajs, &gt, png, style); });
	std::cout << "  (" << map.size() << " points)\n";
	ASSERT_EQ(img.cols, 1500);
	ASSERT_EQ(img.rows, 900);

	const cv::Rect legend = test::findLegend(img);
	ASSERT_FALSE(legend.empty());
	const Rgb rows[] = {kGroundTruthColor, paletteColor(0), kStartInk, kEndFill};
	for (int i = 0; i < 4; ++i) EXPECT_TRUE(test::colorNear(img, test::legendSwatch(legend, i), rows[i], 7)) << i;

	// The paths over the map where the view's camera projects their poses.
	const ViewCamera cam = map3DView(map, trajs, &gt, style);
	auto pixels = [&](const Trajectory& t) {
		std::vector<cv::Point2d> px;
		for (const auto& p : t) px.push_back(cam.project(p.pose.translation()).value());
		return px;
	};
	const std::vector<Line> lines{{pixels(gt), kGroundTruthColor}, {pixels(trajs[0].traj), paletteColor(0)}};
	const auto checked = expectLinesVisible(img, lines, legend, 20, 5);  // the estimate has a 5 px halo
	EXPECT_GE(checked[0], 5) << "ground truth hidden almost everywhere";
	EXPECT_GE(checked[1], 40) << "estimate hidden";

	// The map is drawn in the height colormap (turbo without its darkest tenth): sampled pixels of the view that
	// are neither background nor a path are colormap colours.
	int mapPixels = 0, colormapPixels = 0;
	for (int y = legend.br().y + 10; y < img.rows - 80; y += 3)
		for (int x = 30; x < img.cols - 30; x += 3)
		{
			const cv::Point2d p(x, y);
			const cv::Vec3b c = img.at<cv::Vec3b>(y, x);
			if (c == cv::Vec3b(255, 255, 255) || test::distanceToPolyline(p, lines[0].px) < 12 ||
				test::distanceToPolyline(p, lines[1].px) < 12)
				continue;
			++mapPixels;
			double best = INFINITY;
			for (int k = 0; k <= 200; ++k) best = std::min(best, test::colorDistance(c, turbo(0.1 + 0.9 * k / 200)));
			colormapPixels += best < 12;
		}
	EXPECT_GT(mapPixels, 2000);
	EXPECT_GT(colormapPixels, 0.95 * mapPixels);
}

namespace
{
/// Colours of the rings in the overlay legend of a projected-scan panel, left to right: each entry is a ring on
/// a 19x19 grey tile whose top row is 9 pixels above the legend row (top + 46).
std::vector<cv::Vec3b> panelLegendRings(const cv::Mat& img, int imageRows)
{
	const int y = imageRows + 46;
	const cv::Vec3b tile(128, 128, 128);
	std::vector<cv::Vec3b> rings;
	for (int x = 0, run = 0; x < img.cols; ++x)
	{
		run = img.at<cv::Vec3b>(y - 9, x) == tile ? run + 1 : 0;
		if (run == 19) rings.push_back(img.at<cv::Vec3b>(y, x - 18 + 3));  // ring: radius 6 around tile x + 9
	}
	return rings;
}
}  // namespace

TEST_F(Example, ProjectedScanWithKeypointOverlay)
{
	const auto f = synth::streetFrame(5);
	ProjectedScanStyle style;
	style.title = "frame 0";
	style.max_depth = 40;
	style.point_radius = 1;
	// Pretend keypoints: projected LiDAR points sampled and labelled as a scale corrector would.
	const auto proj = projectScan(f.scan, f.rig, style.min_depth);
	std::mt19937 rng(9);
	ImageOverlay ov;
	const Rgb kept{255, 255, 255}, epi{255, 0, 255}, grad{0, 0, 0};
	ov.legend = {{"kept", kept}, {"rejected: epipolar", epi}, {"rejected: gradient", grad}};
	for (size_t k = 0; k < proj.size(); k += 97)
	{
		const int stage = int(rng() % 3);
		const Rgb c = stage == 0 ? kept : stage == 1 ? epi
													 : grad;
		const cv::Point2d to = proj[k].px + cv::Point2d(8.0 * (proj[k].px.x - 607) / 600, 4.0);
		ov.segments.push_back({proj[k].px, to, c, 1});
		ov.points.push_back({to, c, 4, false});
	}
	const cv::Mat img = renderAndRead("frame_0.png", [&](const std::string& png) {
		renderProjectedScan(f.image, f.scan, f.rig, png, ov, style);
	});
	std::cout << "  (" << f.scan.size() << " points)\n";
	const int W = f.rig.camera.width, H = f.rig.camera.height;
	ASSERT_EQ(img.cols, W);
	ASSERT_EQ(img.rows, H + kProjectedScanPanel);

	// A point is drawn in the colour of its depth where no nearer point's disc and no overlay can reach.
	std::vector<ProjectedPoint> nearFirst = proj;
	std::sort(nearFirst.begin(), nearFirst.end(), [](const auto& a, const auto& b) { return a.depth < b.depth; });
	cv::Mat nearer(H, W, CV_8U, cv::Scalar(0));  // pixels a nearer point's disc may cover
	const int reach = 2 * style.point_radius + 1;
	int probes = 0;
	for (const auto& p : nearFirst)
	{
		const cv::Point c(int(std::lround(p.px.x)), int(std::lround(p.px.y)));
		if (!cv::Rect(0, 0, W, H).contains(c)) continue;
		bool clear = !nearer.at<uint8_t>(c);
		for (const auto& s : ov.segments) clear &= test::distanceToPolyline(p.px, {s.from, s.to}) > 3;
		for (const auto& o : ov.points) clear &= cv::norm(p.px - o.px) > o.radius + 4;
		nearer(cv::Rect(c.x - reach, c.y - reach, 2 * reach + 1, 2 * reach + 1) & cv::Rect(0, 0, W, H)).setTo(255);
		if (!clear) continue;
		EXPECT_LT(test::colorDistance(img.at<cv::Vec3b>(c), turbo(p.depth / style.max_depth)), 1.0)
			<< "point at " << p.px << ", " << p.depth << " m";
		++probes;
	}
	EXPECT_GT(probes, 1000);
	// Overlay markers in their colours (rings of radius 4: the pixel 4 to the right of the centre).
	for (size_t k = 0; k < ov.points.size(); k += 10)
		EXPECT_TRUE(test::colorNear(img, ov.points[k].px + cv::Point2d(4, 0), ov.points[k].color, 1, 40)) << k;
	// Legend: one ring per entry, in the entries' order and colours.
	const auto rings = panelLegendRings(img, H);
	ASSERT_EQ(rings.size(), ov.legend.size());
	for (size_t k = 0; k < rings.size(); ++k)
		EXPECT_LT(test::colorDistance(rings[k], ov.legend[k].second), 40) << ov.legend[k].first;
}

TEST_F(Example, ScaleOverTime)
{
	// The estimate scatters around a correction that decays while oscillating: above 1, then crossing it at
	// t = 5 s (cos(pi t / 10) = 0) on its way down.
	Series s{"scale estimate", {}, {}, {}, true, false}, c{"applied correction", {}, {}, {}, false, true};
	std::mt19937 rng(4);
	std::normal_distribution<double> n(0, 0.015);
	for (int k = 0; k < 300; ++k)
	{
		const double t = 0.1 * k, correction = 1 + 0.06 * std::exp(-t / 8) * std::cos(M_PI * t / 10);
		s.x.push_back(t);
		s.y.push_back(k % 37 == 5 ? NAN : correction + n(rng));
		c.x.push_back(t);
		c.y.push_back(correction);
	}
	SeriesStyle style;
	style.width = 1100, style.height = 450;
	style.title = "Scale estimate over time";
	style.ylabel = "scale s = d_lidar / d_visual";
	style.reference_y = 1.0;
	const cv::Mat img = renderAndRead("scale.png", [&](const std::string& png) { renderSeries({s, c}, png, style); });
	ASSERT_EQ(img.cols, 1100);
	ASSERT_EQ(img.rows, 450);
	const cv::Rect legend = test::findLegend(img);
	ASSERT_FALSE(legend.empty());
	EXPECT_TRUE(test::colorNear(img, test::legendSwatch(legend, 0), paletteColor(0), 1));
	EXPECT_TRUE(test::colorNear(img, test::legendSwatch(legend, 1), paletteColor(1), 1));

	// On the reference row, the correction's line first appears at the column of t = 5 s.
	const PlotArea a = seriesArea({s, c}, style);
	const cv::Point2d cross = a.toPixel(5.0, 1.0);
	const int row = int(std::lround(cross.y));
	int first = -1;
	for (int x = a.rect.x; x < a.rect.br().x && first < 0; ++x)
		if (!legend.contains({x, row}) && test::colorDistance(img.at<cv::Vec3b>(row, x), paletteColor(1)) < 30) first = x;
	EXPECT_NEAR(first, cross.x, 3);
	// Every finite estimate is a dot of its colour, except under the correction's line or the legend.
	std::vector<cv::Point2d> line;
	for (size_t k = 0; k < c.x.size(); ++k) line.push_back(a.toPixel(c.x[k], c.y[k]));
	const cv::Rect nearLegend(legend.x - 4, legend.y - 4, legend.width + 8, legend.height + 8);
	int dots = 0;
	for (size_t k = 0; k < s.x.size(); ++k)
	{
		const cv::Point2d p = a.toPixel(s.x[k], s.y[k]);
		if (!std::isfinite(s.y[k]) || !a.rect.contains(p) || test::distanceToPolyline(p, line) < 5 ||
			nearLegend.contains(p))
			continue;
		EXPECT_TRUE(test::colorNear(img, p, paletteColor(0), 0)) << "sample " << k;
		++dots;
	}
	EXPECT_GT(dots, 200);
}
