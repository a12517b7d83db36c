// Realistic examples for reviewers: writes <build>/viz_examples/*.png and prints render times.
#include <gtest/gtest.h>
#include <vlo/io/pcd.h>
#include <vlo/viz/map3d.h>
#include <vlo/viz/projected_scan.h>
#include <vlo/viz/series.h>
#include <vlo/viz/topdown.h>

#include "synthetic.h"

#include <mrpt/system/filesystem.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <random>

using namespace vlo;

namespace
{
const std::string kOut = std::string(VLO_BIN_DIR) + "/../viz_examples/";

template <typename F>
double millis(F&& f)
{
	const auto t0 = std::chrono::steady_clock::now();
	f();
	return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

struct Example : ::testing::Test
{
	static void SetUpTestSuite() { mrpt::system::createDirectory(kOut); }
};
}  // namespace

TEST_F(Example, TopDownOfAOneKilometreDrive)
{
	const Trajectory gt = synth::curvedDrive(1000);
	const std::vector<NamedTrajectory> trajs{{"vlo (VO + LiDAR)", synth::driftingEstimate(gt, 0.01, 2e-5, 1, 1), {}},
		{"VO only", synth::driftingEstimate(gt, -0.12, 1.2e-4, 2, 2), {}}};
	TopDownStyle style;
	style.title = "Trajectories, top-down (synthetic urban drive)";
	const double ms = millis([&] { renderTopDown(trajs, &gt, kOut + "topdown.png", style); });
	std::cout << "topdown.png: " << ms << " ms\n";
	EXPECT_TRUE(mrpt::system::fileExists(kOut + "topdown.png"));
}

TEST_F(Example, Map3DOfAStreet)
{
	const Trajectory gt = synth::curvedDrive(1000);
	const PointCloud map = synth::streetMap(gt, 3);
	writePcd(kOut + "street_map.pcd", map);
	const Trajectory est = synth::driftingEstimate(gt, 0.01, 2e-5, 1, 1);
	Map3DStyle style;
	style.title = "Map and trajectory (synthetic street)";
	const double ms =
		millis([&] { renderMap3D(map, {{"vlo (VO + LiDAR)", est, {}}}, &gt, kOut + "map3d.png", style); });
	std::cout << "map3d.png (" << map.size() << " points): " << ms << " ms\n";
	EXPECT_TRUE(mrpt::system::fileExists(kOut + "map3d.png"));
}

TEST_F(Example, ProjectedScanWithKeypointOverlay)
{
	const auto f = synth::streetFrame(5);
	// Pretend keypoints: projected LiDAR points sampled and labelled as a scale corrector would.
	const auto proj = projectScan(f.scan, f.rig, 2.0);
	std::mt19937 rng(9);
	ImageOverlay ov;
	const Rgb kept{255, 255, 255}, epi{255, 0, 255}, grad{0, 0, 0};
	ov.legend = {{"kept", kept}, {"rejected: epipolar", epi}, {"rejected: gradient", grad}};
	for (size_t k = 0; k < proj.size(); k += 97)
	{
		const int stage = int(rng() % 3);
		const Rgb c = stage == 0 ? kept : stage == 1 ? epi : grad;
		const cv::Point2d to = proj[k].px + cv::Point2d(8.0 * (proj[k].px.x - 607) / 600, 4.0);
		ov.segments.push_back({proj[k].px, to, c, 1});
		ov.points.push_back({to, c, 4, false});
	}
	ProjectedScanStyle style;
	style.title = "frame 0";
	const double ms = millis([&] { renderProjectedScan(f.image, f.scan, f.rig, kOut + "frame_0.png", ov, style); });
	std::cout << "frame_0.png (" << f.scan.size() << " points): " << ms << " ms\n";
}

TEST_F(Example, ScaleOverTime)
{
	Series s{"scale estimate", {}, {}, {}, true, false}, c{"applied correction", {}, {}, {}, false, true};
	std::mt19937 rng(4);
	std::normal_distribution<double> n(0, 0.015);
	for (int k = 0; k < 300; ++k)
	{
		s.x.push_back(0.1 * k);
		s.y.push_back(k % 37 == 5 ? NAN : 1 + 0.06 * std::exp(-k / 80.0) + n(rng));
		c.x.push_back(0.1 * k);
		c.y.push_back(1 + 0.06 * std::exp(-k / 80.0));
	}
	SeriesStyle style;
	style.title = "Scale estimate over time";
	style.ylabel = "scale s = d_lidar / d_visual";
	style.reference_y = 1.0;
	const double ms = millis([&] { renderSeries({s, c}, kOut + "scale.png", style); });
	std::cout << "scale.png: " << ms << " ms\n";
}
