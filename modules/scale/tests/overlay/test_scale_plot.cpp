// scale.png from a constructed history: each number where the panels' mappings put it, in its colour, and a legend
// entry for every series of each panel.
#include <gtest/gtest.h>
#include <vlo/scale/scale_plot.h>

#include "../../../viz/tests/test_util.h"

#include <cmath>

using namespace vlo;
using namespace vlo::scale;

namespace
{
/// 60 frames: no metric map before frame 5 (the initial scale), then estimates 1 + 0.03 sin(k / 4); corrections 1.04
/// at frame 20 and 0.97 at frame 40, so the cumulative factor is 1, then 1.04, then 1.04 * 0.97 = 1.0088; frame 30
/// and 31 have no valid estimate (0 inliers) but rejected ones of 1.01 and 3 (off the plot); the
/// inlier count is 100 + k otherwise.
ScaleHistory history()
{
	ScaleHistory h;
	double cum = -1;
	for (int k = 0; k < 60; ++k)
	{
		const double correction = k == 20 ? 1.04 : k == 40 ? 0.97
														   : 1.0;
		cum = k == 5 ? 1.0 : cum * correction;
		const bool none = k < 5 || k == 30 || k == 31;
		const double rejected = k == 30 ? 1.01 : k == 31 ? 3.0
														 : NAN;
		h.add(k, none ? NAN : 1 + 0.03 * std::sin(k / 4.0), none ? 0 : 100 + k, correction, cum, rejected);
	}
	return h;
}
}  // namespace

TEST(ScalePlot, HistoryKeepsNanWhereThereIsNoValue)
{
	const ScaleHistory h = history();
	ASSERT_EQ(h.frame.size(), 60u);
	EXPECT_TRUE(std::isnan(h.cumulative[4]));
	EXPECT_DOUBLE_EQ(h.cumulative[5], 1.0);
	EXPECT_NEAR(h.cumulative[59], 1.04 * 0.97, 1e-12);
	EXPECT_TRUE(std::isnan(h.correction[19]));
	EXPECT_DOUBLE_EQ(h.correction[20], 1.04);
	EXPECT_TRUE(std::isnan(h.estimate[30]));
	EXPECT_EQ(h.inliers[30], 0);
}

TEST(ScalePlot, EachValueIsWhereThePanelsPutIt)
{
	const ScaleHistory h = history();
	const auto panels = scalePlotPanels(h);
	ASSERT_EQ(panels.size(), 2u);
	const cv::Mat img = drawSeriesPanels(panels);
	const auto areas = seriesPanelAreas(panels);
	ASSERT_EQ(img.rows, panels[0].style.height + panels[1].style.height);
	// One x axis: frame k is on the same column in both panels.
	EXPECT_NEAR(areas[0].toPixel(17, 1).x, areas[1].toPixel(17, 0).x, 1e-9);

	const viz::Rgb rejected = *panels[0].series[0].color, estimate = *panels[0].series[1].color,
				   cumulative = *panels[0].series[2].color, correction = *panels[0].series[3].color,
				   inliers = *panels[1].series[0].color;
	EXPECT_TRUE(test::colorNear(img, areas[0].toPixel(30, 1.01), rejected, 0, 10));
	EXPECT_LT(areas[0].ymax, 1.2);  // the rejected 3.0 does not squash the rest
	// The cumulative factor as steps: 1 up to frame 20, 1.04 up to 40, then 1.0088 (between the samples, away from
	// the estimates' dots).
	for (auto [x, y] : {std::pair{12.5, 1.0}, {27.5, 1.04}, {52.5, 1.04 * 0.97}})
		EXPECT_TRUE(test::colorNear(img, areas[0].toPixel(x, y), cumulative, 1)) << x;
	// ... and vertical at each correction, where the correction's marker is drawn on top.
	EXPECT_TRUE(test::colorNear(img, areas[0].toPixel(20, 1.02), cumulative, 1));
	EXPECT_TRUE(test::colorNear(img, areas[0].toPixel(20, 1.04), correction, 1, 10));
	EXPECT_TRUE(test::colorNear(img, areas[0].toPixel(40, 0.97), correction, 1, 10));
	// Estimates that no line or marker covers (the last one is on the plot's right edge: half a dot).
	int dots = 0;
	for (int k = 6; k < 59; ++k)
	{
		const double y = 1 + 0.03 * std::sin(k / 4.0), cum = k < 20 ? 1.0 : k < 40 ? 1.04
																				   : 1.04 * 0.97;
		if (k == 30 || k == 31 || std::abs(areas[0].toPixel(k, y).y - areas[0].toPixel(k, cum).y) < 6 || k == 20 || k == 40)
			continue;
		EXPECT_TRUE(test::colorNear(img, areas[0].toPixel(k, y), estimate, 0, 10)) << k;
		++dots;
	}
	EXPECT_GT(dots, 30);
	// Dots, not a line: nothing of their colour halfway between two of them (18 pixels apart).
	for (int k : {8, 13, 33, 47})
	{
		const double y = 1 + 0.015 * (std::sin(k / 4.0) + std::sin((k + 1) / 4.0));
		EXPECT_FALSE(test::colorNear(img, areas[0].toPixel(k + 0.5, y), estimate, 2, 60)) << k;
		EXPECT_FALSE(test::colorNear(img, areas[1].toPixel(k + 0.5, 100.5 + k), inliers, 2, 60)) << k;
	}
	// Inliers: 100 + k, and 0 where there was no estimate.
	for (int k : {10, 25, 45, 55}) EXPECT_TRUE(test::colorNear(img, areas[1].toPixel(k, 100 + k), inliers, 0, 10)) << k;
	EXPECT_TRUE(test::colorNear(img, areas[1].toPixel(30, 0), inliers, 1, 10));
	EXPECT_FALSE(test::colorNear(img, areas[1].toPixel(30, 130), inliers, 3, 60));
}

TEST(ScalePlot, EveryLegendEntryShowsItsColour)
{
	const auto panels = scalePlotPanels(history());
	const cv::Mat img = drawSeriesPanels(panels);
	int top = 0;
	for (const auto& p : panels)
	{
		const cv::Mat panel = img(cv::Rect(0, top, img.cols, p.style.height));
		top += p.style.height;
		const cv::Rect legend = test::findLegend(panel);
		ASSERT_FALSE(legend.empty());
		EXPECT_EQ(legend.height, 2 * 10 + 24 * int(p.series.size()) - 6) << "one row per series";
		for (std::size_t i = 0; i < p.series.size(); ++i)
			EXPECT_TRUE(test::colorNear(panel, test::legendSwatch(legend, int(i)), *p.series[i].color, 2, 10))
				<< p.series[i].name;
	}
}

TEST(ScalePlot, TheLegendNamesOnlyWhatAppears)
{
	ScaleHistory h;
	for (int k = 0; k < 10; ++k) h.add(k, 1 + 0.01 * k, 50, 1.0, 1.0);  // no rejection, no correction
	const auto panels = scalePlotPanels(h);
	ASSERT_EQ(panels[0].series.size(), 2u);
	EXPECT_TRUE(*panels[0].series[0].color == *scalePlotPanels(history())[0].series[1].color);  // the estimates
	EXPECT_TRUE(*panels[0].series[1].color == *scalePlotPanels(history())[0].series[2].color);  // the cumulative factor
}

TEST(ScalePlot, NothingToPlotWritesNothing)
{
	ScaleHistory h;
	h.add(3, NAN, 0, 1.0, -1);
	EXPECT_FALSE(renderScalePlot(h, "/nonexistent/scale.png"));
}
