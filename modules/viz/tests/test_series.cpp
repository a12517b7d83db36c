#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/viz/series.h>

#include "test_util.h"

#include <cmath>

using namespace vlo;

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
