// vlo-eval's plots from constructed estimates whose KITTI curves and ATE are known in closed form.
#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/viz/eval_plots.h>
#include <vlo/viz/topdown.h>

#include "test_util.h"

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <filesystem>

using namespace vlo;
using namespace vlo::viz;

namespace
{
/// A straight drive along x, 1001 poses 0.9 m apart at 10 Hz (9 m/s), positions scaled by s.
Trajectory straight(double s)
{
	Trajectory t(1001);
	for (std::size_t i = 0; i < t.size(); ++i)
	{
		t[i].t = 0.1 * double(i);
		t[i].pose.translation() = Eigen::Vector3d(s * 0.9 * double(i), 0, 0);
	}
	return t;
}

std::vector<EvalRun> twoRuns()
{
	const Trajectory gt = straight(1);
	eval::EvalOptions o;
	return {{"five percent", eval::evaluate(gt, straight(1.05), o)}, {"two percent", evaluate(gt, straight(1.02), o)}};
}
}  // namespace

TEST(EvalPlots, DevkitCurvesOfAConstantScaleError)
{
	// A segment of length L covers n_L = floor(L / 0.9) + 1 steps: its translation error is k n_L 0.9 / L
	// for an estimate k too long (test_kitti_curves.cpp); it goes at 8.85..8.99 m/s, the points 8 and 10 m/s.
	const auto plots = kittiErrorPlots(twoRuns());
	ASSERT_EQ(plots.size(), 4u);
	const PlotSpec& tl = plots[0];
	EXPECT_EQ(tl.file, "kitti_translation_vs_length.png");
	EXPECT_EQ(tl.style.ylabel, "translation error [%]");
	ASSERT_EQ(tl.series.size(), 2u);
	const double k[] = {0.05, 0.02};
	for (std::size_t r = 0; r < 2; ++r)
	{
		ASSERT_EQ(tl.series[r].y.size(), 8u);
		for (std::size_t i = 0; i < 8; ++i)
		{
			const double L = 100.0 * double(i + 1);
			EXPECT_EQ(tl.series[r].x[i], L);
			EXPECT_NEAR(tl.series[r].y[i], 100 * k[r] * (std::floor(L / 0.9) + 1) * 0.9 / L, 1e-9);
		}
	}
	EXPECT_EQ(plots[1].file, "kitti_rotation_vs_length.png");
	for (const double y : plots[1].series[0].y) EXPECT_NEAR(y, 0, 1e-9);
	const PlotSpec& ts = plots[2];
	EXPECT_EQ(ts.file, "kitti_translation_vs_speed.png");
	EXPECT_EQ(ts.style.xlabel, "speed [km/h]");
	ASSERT_EQ(ts.series[0].x.size(), 2u);
	EXPECT_NEAR(ts.series[0].x[0], 8 * 3.6, 1e-12);
	EXPECT_NEAR(ts.series[0].x[1], 10 * 3.6, 1e-12);
	EXPECT_NEAR(ts.series[0].y[0], 5 * 1.0030942, 1e-5);  // all 404 segments: 5 % times the overshoot factor
	EXPECT_NEAR(ts.series[1].y[1], 2 * 1.0030942, 1e-5);
}

TEST(EvalPlots, EachLegendEntryShowsItsColour)
{
	const auto plots = kittiErrorPlots(twoRuns());
	const cv::Mat img = drawSeries(plots[0].series, plots[0].style);
	const cv::Rect box = test::findLegend(img);
	ASSERT_FALSE(box.empty());
	for (int i = 0; i < 2; ++i)
	{
		const cv::Point2d sw = test::legendSwatch(box, i);
		EXPECT_TRUE(box.contains(cv::Point(sw)));
		EXPECT_TRUE(test::colorNear(img, sw, paletteColor(std::size_t(i)), 2, 20)) << i;
	}
}

TEST(EvalPlots, ShortDriveHasNoDevkitPlotButAnAtePlot)
{
	const Trajectory gt = straight(1);
	const Trajectory shortGt(gt.begin(), gt.begin() + 50), shortEst(shortGt.begin(), shortGt.end());
	const std::vector<EvalRun> runs{{"short/one", eval::evaluate(shortGt, shortEst, eval::EvalOptions{})}};
	EXPECT_TRUE(kittiErrorPlots(runs).empty());
	const std::string dir = testing::TempDir() + "/eval_plots_short";
	std::filesystem::remove_all(dir);
	const auto files = writeEvalPlots(dir, runs);
	ASSERT_EQ(files, std::vector<std::string>{"ate_short_one.png"});
	EXPECT_FALSE(cv::imread(dir + "/" + files[0]).empty());
}

TEST(TopDown, PathColouredByValuesShowsThemOnTheTurboScale)
{
	// Values growing from 0 to 4 along a straight path: its start is turbo(0), its end turbo(1).
	const NamedTrajectory t{"est", straight(0.1), {}};
	TopDownStyle style;
	for (std::size_t i = 0; i < t.traj.size(); ++i) style.values.push_back(4.0 * double(i) / double(t.traj.size() - 1));
	style.value_label = "ATE [m]";
	const cv::Mat img = drawTopDown({t}, nullptr, style);
	const PlotArea a = topDownArea({t}, nullptr, style);
	const auto at = [&](std::size_t i) {
		const auto& p = t.traj[i].pose.translation();
		return a.toPixel(p.x(), p.y());
	};
	EXPECT_TRUE(test::colorNear(img, at(100), turbo(0.1), 1, 25));
	EXPECT_TRUE(test::colorNear(img, at(500), turbo(0.5), 1, 25));
	EXPECT_TRUE(test::colorNear(img, at(900), turbo(0.9), 1, 25));
	style.values.pop_back();
	EXPECT_THROW(drawTopDown({t}, nullptr, style), InputError);
}
