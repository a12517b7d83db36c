#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/viz/series.h>

#include "test_util.h"

#include <cmath>

using namespace vlo;
using namespace vlo::viz;

TEST(Series, LineAppearsWhereTheMappingSaysAndNanLeavesAGap)
{
	Series s{"scale", {}, {}, Rgb{200, 0, 0}, false, true};
	for (int k = 0; k <= 100; ++k)
	{
		s.x.push_back(0.1 * k);
		s.y.push_back(k >= 40 && k < 60 ? NAN : 1.0 + 0.01 * k);
	}
	SeriesStyle style;
	style.reference_y = 1.0;
	const cv::Mat img = drawSeries({s}, style);
	ASSERT_EQ(img.cols, style.width);
	ASSERT_EQ(img.rows, style.height);
	const PlotArea a = seriesArea({s}, style);
	for (int k : {10, 20, 30, 70, 80, 90})
		EXPECT_TRUE(test::colorNear(img, a.toPixel(0.1 * k, 1 + 0.01 * k), s.color.value(), 1)) << k;
	EXPECT_FALSE(test::colorNear(img, a.toPixel(5.0, 1.5), s.color.value(), 3, 60));  // the gap
}

TEST(Series, BadInputIsAnInputError)
{
	EXPECT_THROW(drawSeries({{"a", {1, 2}, {1}, {}, false, true}}), InputError);
	EXPECT_THROW(drawSeries({{"a", {1}, {NAN}, {}, false, true}}), InputError);
	EXPECT_NO_THROW(drawSeries({{"one sample", {1}, {2}, {}, true, false}}));
}

TEST(Series, FillStacksEachSeriesOnThePreviousOneInATintOfItsColour)
{
	// Two stacked stages: 10 ms, then 20 ms more (y = 30); frames 4-5 of the second have no value: a gap.
	Series a{"a", {}, {}, Rgb{0, 114, 178}, false, true}, b{"b", {}, {}, Rgb{213, 94, 0}, false, true};
	a.fill = b.fill = true;
	for (int k = 0; k <= 10; ++k)
	{
		a.x.push_back(k), a.y.push_back(10);
		b.x.push_back(k), b.y.push_back(k == 4 || k == 5 ? NAN : 30);
	}
	SeriesStyle style;
	style.ymin = 0, style.ymax = 40;
	style.reference_y = 25;  // a budget line inside b's band
	style.legend_outside = true;
	const cv::Mat img = drawSeries({a, b}, style);
	const PlotArea area = seriesArea({a, b}, style);
	const auto tint = [](Rgb c) { return Rgb{std::uint8_t(c.r / 2 + 128), std::uint8_t(c.g / 2 + 128), std::uint8_t(c.b / 2 + 128)}; };
	for (double x : {2.5, 7.5})  // away from the legend in a corner and the x grid lines
	{
		EXPECT_TRUE(test::colorNear(img, area.toPixel(x, 5), tint(*a.color), 0, 2)) << x;  // 0..10: a
		EXPECT_TRUE(test::colorNear(img, area.toPixel(x, 20), tint(*b.color), 0, 2)) << x;  // 10..30: b
		EXPECT_TRUE(test::colorNear(img, area.toPixel(x, 37.5), {255, 255, 255}, 0, 2)) << x;  // above (between grid lines)
	}
	// The reference line's dashes show above the fill.
	int dashes = 0;
	const cv::Point2d ref = area.toPixel(0, 25);
	for (int x = area.rect.x; x < area.rect.br().x; ++x)
		dashes += test::colorDistance(img.at<cv::Vec3b>(int(std::lround(ref.y)), x), {40, 40, 40}) < 30;
	EXPECT_GT(dashes, area.rect.width / 3);
	// The legend is right of the plot area, not over it.
	const cv::Rect legend = test::findLegend(img);
	EXPECT_GE(legend.x, area.rect.br().x);
	EXPECT_TRUE(test::colorNear(img, test::legendSwatch(legend, 1), *b.color, 1));
	EXPECT_TRUE(test::colorNear(img, area.toPixel(4.5, 5), tint(*a.color), 0, 2));
	EXPECT_FALSE(test::colorNear(img, area.toPixel(4.5, 20), tint(*b.color), 3, 20));  // b's gap is not filled
	// Filling down to a series with other x values cannot be drawn.
	b.x.back() = 11;
	EXPECT_THROW(drawSeries({a, b}, style), InputError);
}

TEST(Series, PanelsShareTheXAxisAndStackTopToBottom)
{
	SeriesPanel top{{{"early", {0, 10}, {1, 2}, Rgb{0, 114, 178}, false, true}}, {}},
		bottom{{{"late", {5, 20}, {3, 4}, Rgb{213, 94, 0}, false, true}}, {}};
	top.style.height = 300, bottom.style.height = 200, bottom.style.width = 500;  // the first panel's width wins
	const cv::Mat img = drawSeriesPanels({top, bottom});
	ASSERT_EQ(img.rows, 500);
	ASSERT_EQ(img.cols, top.style.width);
	const auto areas = seriesPanelAreas({top, bottom});
	ASSERT_EQ(areas.size(), 2u);
	for (const auto& a : areas)
	{
		EXPECT_EQ(a.xmin, 0);
		EXPECT_EQ(a.xmax, 20);
	}
	EXPECT_EQ(areas[0].rect.x, areas[1].rect.x);
	EXPECT_EQ(areas[0].rect.width, areas[1].rect.width);
	EXPECT_GE(areas[1].rect.y, 300);
	EXPECT_TRUE(test::colorNear(img, areas[0].toPixel(5, 1.5), *top.series[0].color, 1));
	EXPECT_TRUE(test::colorNear(img, areas[1].toPixel(12.5, 3.5), *bottom.series[0].color, 1));
	EXPECT_THROW(drawSeriesPanels({}), InputError);
}
