// What the scale corrector's decisions do to the VO: a drift correction scales the map about the local
// window's earliest keyframe, the metric scale of a fresh map scales it about its origin; the output
// trajectory stays continuous and later motions come in the new units.
#include <gtest/gtest.h>

#include "vo_test_util.h"

using namespace vlo;
using namespace vlo::vo;

namespace
{
struct Driven
{
	Driven() : cam(test::kittiCamera()), vo(std::make_unique<VisualOdometry>(cam, VoOptions())), renderer(test::StreetScene(), cam) {}

	PinholeCamera cam;
	std::unique_ptr<VisualOdometry> vo;
	test::StreetRenderer renderer;
	int k = 0;
	VoFrameInfo last;  ///< of the last frame fed
};

void drive(Driven& d, int frames)
{
	for (int i = 0; i < frames; ++i, ++d.k) d.last = d.vo->process(d.renderer.render(test::drivePose(d.k)), 0.1 * d.k);
}
}  // namespace

TEST(ScaleInterface, RescaleAboutTheWindowKeepsTheOutputAndScalesLaterMotions)
{
	Driven d;
	drive(d, 25);
	ASSERT_EQ(d.last.state, VoState::Ok);
	ASSERT_GE(d.last.keyframes, 2);
	ASSERT_GT(d.last.map_points, 100);

	const double s = 2.5;
	ASSERT_TRUE(d.vo->rescaleAboutWindow(s));
	// Tracking goes on in the new scale: later motions are s times longer, the output continues.
	const auto prev = d.last;
	drive(d, 1);
	EXPECT_LT((d.last.pose->translation() - prev.pose->translation()).norm(), 1.5 * s * prev.motion->translation().norm());
	drive(d, 2);
	ASSERT_EQ(d.last.state, VoState::Ok);
	ASSERT_TRUE(d.last.motion && prev.motion);
	const double ratio = d.last.motion->translation().norm() / prev.motion->translation().norm();
	EXPECT_NEAR(ratio, s, 0.15 * s);
}

TEST(ScaleInterface, MapScaleAfterInitialisation)
{
	Driven d;
	EXPECT_FALSE(d.vo->setMapScale(2.0));  // no map yet
	EXPECT_FALSE(d.vo->rescaleAboutWindow(2.0));
	while (!d.last.new_map && d.k < 10) drive(d, 1);
	ASSERT_TRUE(d.last.new_map);
	EXPECT_FALSE(d.last.metric);
	// The true motion per frame is ~1 m; with that metric scale the next motions are ~1 m.
	drive(d, 1);
	ASSERT_TRUE(d.last.motion);
	ASSERT_TRUE(d.vo->setMapScale(1.0 / d.last.motion->translation().norm()));
	drive(d, 5);
	ASSERT_EQ(d.last.state, VoState::Ok);
	EXPECT_TRUE(d.last.metric);
	EXPECT_NEAR(d.last.motion->translation().norm(), 1.0, 0.1);
}
