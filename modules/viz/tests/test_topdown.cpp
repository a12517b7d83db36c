#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/viz/topdown.h>

#include "../src/canvas.h"
#include "test_util.h"

#include <opencv2/imgcodecs.hpp>

using namespace vlo;
using namespace vlo::viz;

namespace
{
/// A straight diagonal from (0, 0) to (100, 100) m, offset sideways by `dy`: the upper-left and
/// lower-right corners stay empty for the legend and scale bar.
Trajectory diagonal(double dy)
{
	Trajectory t;
	for (int k = 0; k <= 100; ++k)
	{
		StampedPose p;
		p.t = k;
		p.pose.translation() = Eigen::Vector3d(k, k + dy, 0);
		t.push_back(p);
	}
	return t;
}
}  // namespace

TEST(TopDown, MappingHasEqualAspectAndContainsEveryPose)
{
	const std::vector<NamedTrajectory> trajs{{"est", diagonal(-8), {}}};
	const Trajectory gt = diagonal(0);
	TopDownStyle style;
	style.width = 900, style.height = 600;
	const PlotArea a = topDownArea(trajs, &gt, style);
	const cv::Point2d p0 = a.toPixel(0, 0), p1 = a.toPixel(100, 100);
	EXPECT_NEAR(p1.x - p0.x, -(p1.y - p0.y), 1e-9);  // equal aspect: 100 m is as long on both axes
	EXPECT_GT(p1.x, p0.x);  // x grows to the right
	EXPECT_LT(p1.y, p0.y);  // y grows upwards on screen
	for (const auto* t : {&gt, &trajs[0].traj})
		for (const auto& p : *t)
			EXPECT_TRUE(a.rect.contains(a.toPixel(p.pose.translation().x(), p.pose.translation().y())));
}

TEST(TopDown, TrajectoryAndGroundTruthAppearWhereTheMappingSays)
{
	const Rgb red{220, 30, 30};
	const std::vector<NamedTrajectory> trajs{{"est", diagonal(-8), red}, {"other", diagonal(-16), {}}};
	const Trajectory gt = diagonal(0);
	TopDownStyle style;
	style.width = 900, style.height = 700;
	const cv::Mat img = drawTopDown(trajs, &gt, style);
	ASSERT_EQ(img.cols, 900);
	ASSERT_EQ(img.rows, 700);
	ASSERT_EQ(img.type(), CV_8UC3);
	const PlotArea a = topDownArea(trajs, &gt, style);
	for (int k = 10; k <= 90; k += 5)  // away from the start and end markers
	{
		EXPECT_TRUE(test::colorNear(img, a.toPixel(k, k - 8), red, 1)) << k;
		EXPECT_TRUE(test::colorNear(img, a.toPixel(k, k - 16), paletteColor(1), 1)) << k;
		EXPECT_TRUE(test::colorNear(img, a.toPixel(k, k), kGroundTruthColor, 1)) << k;
		// Halfway between GT and the estimate there is only background.
		EXPECT_TRUE(test::colorNear(img, a.toPixel(k, k - 4), Rgb{255, 255, 255}, 0, 50)) << k;  // or grid
	}
	// End marker: a filled square of the trajectory's colour centred on the last pose.
	EXPECT_TRUE(test::colorNear(img, a.toPixel(100, 92), red, 0, 1));
}

TEST(TopDown, WritesPngOfTheRequestedSize)
{
	const std::string png = ::testing::TempDir() + "vlo_topdown.png";
	TopDownStyle style;
	style.width = 640, style.height = 480;
	style.title = "test";
	renderTopDown({{"est", diagonal(3), {}}}, nullptr, png, style);
	const cv::Mat back = cv::imread(png, cv::IMREAD_UNCHANGED);
	ASSERT_FALSE(back.empty());
	EXPECT_EQ(back.cols, 640);
	EXPECT_EQ(back.rows, 480);
	EXPECT_EQ(back.channels(), 3);
}

TEST(TopDown, NothingToDrawIsAnInputError)
{
	EXPECT_THROW(drawTopDown({{"empty", {}, {}}}, nullptr), InputError);
	EXPECT_THROW(drawTopDown({}, nullptr), InputError);
	// A single pose still draws (degenerate extent).
	const Trajectory one{diagonal(0).front()};
	EXPECT_NO_THROW(drawTopDown({{"one", one, {}}}, nullptr));
}

TEST(TopDown, FailedWriteLeavesNoFile)
{
	const std::string png = ::testing::TempDir() + "no_such_dir/x.png";
	EXPECT_THROW(renderTopDown({{"est", diagonal(0), {}}}, nullptr, png), InputError);
}

TEST(TopDown, OneStartRingForTheDriveAndADiamondWhereALaterPathBegins)
{
	const Trajectory a = diagonal(0), late(a.begin() + 30, a.end());
	const cv::Mat together = drawTopDown({{"lo", a, {}}, {"vo", a, {}}}, nullptr);
	const cv::Rect box2 = test::findLegend(together);
	EXPECT_EQ(box2.height, 2 * 10 + 24 * 4 - 6);  // lo, vo, start, end: no diamond row

	const std::vector<NamedTrajectory> trajs{{"lo", a, {}}, {"vo", late, {}}};
	const cv::Mat img = drawTopDown(trajs, nullptr);
	const PlotArea area = topDownArea(trajs, nullptr);
	const cv::Rect box = test::findLegend(img);
	EXPECT_EQ(box.height, 2 * 10 + 24 * 5 - 6);
	EXPECT_TRUE(test::colorNear(img, test::legendSwatch(box, 3), Rgb{200, 200, 200}, 2, 10));  // the diamond row
	const auto& p = late.front().pose.translation();
	EXPECT_TRUE(test::colorNear(img, area.toPixel(p.x(), p.y()), paletteColor(1), 2, 10));  // diamond in vo's colour
	EXPECT_TRUE(test::colorNear(img, area.toPixel(0, 0), Rgb{255, 255, 255}, 1, 10));  // the ring's white centre
}

TEST(TopDown, LinksAreDrawnBetweenTheirEndsAndCounted)
{
	const std::vector<NamedTrajectory> trajs{{"est", diagonal(-8), {}}, {"other", diagonal(8), {}}};
	TopDownStyle style;
	style.links = {{Eigen::Vector3d(50, 42, 0), Eigen::Vector3d(50, 58, 0)}};
	const cv::Mat img = drawTopDown(trajs, nullptr, style);
	const PlotArea a = topDownArea(trajs, nullptr, style);
	for (double y : {46.0, 50.0, 54.0}) EXPECT_TRUE(test::colorNear(img, a.toPixel(50, y), style.links_color, 1, 40)) << y;
	EXPECT_FALSE(test::colorNear(img, a.toPixel(30, 30), style.links_color, 3, 40));  // nowhere else
	const cv::Mat without = drawTopDown(trajs, nullptr);
	EXPECT_EQ(test::findLegend(img).height, test::findLegend(without).height + 24);  // one legend row more
}

TEST(ColorBar, TickLabelsNeverTouch)
{
	// An ATE of up to 34 mm on a 260-pixel bar: five ticks (0.005 m) would need "0.000" ... "0.030" side by side,
	// wider than 52 pixels each; every 0.01 m they fit. A depth bar 0-40 m keeps its ticks every 10 m.
	EXPECT_DOUBLE_EQ(canvas::colorBarStep(0, 0.034, 260), 0.01);
	EXPECT_DOUBLE_EQ(canvas::colorBarStep(0, 40, 320), 10);
	EXPECT_DOUBLE_EQ(canvas::colorBarStep(0, 1e6, 60), 1e6);  // no room: the ends only
}
