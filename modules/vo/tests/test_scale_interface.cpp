// The interface of the scale corrector: rescaling the local window about its earliest keyframe,
// the metric scale of a fresh map, and the per-frame data it reads.
#include <gtest/gtest.h>

#include "vo_test_util.h"

using namespace vlo;
using namespace vlo::vo;

namespace
{
struct Driven
{
	std::unique_ptr<VisualOdometry> vo;
	test::StreetRenderer renderer;
	int k = 0;
};

void drive(Driven& d, int frames)
{
	for (int i = 0; i < frames; ++i, ++d.k) d.vo->process(d.renderer.render(test::drivePose(d.k)), 0.1 * d.k);
}
}  // namespace

TEST(ScaleInterface, RescaleScalesTheWindowAboutItsEarliestKeyframe)
{
	const auto cam = test::kittiCamera();
	Driven d{std::make_unique<VisualOdometry>(cam, VoOptions()), test::StreetRenderer(test::StreetScene(), cam)};
	drive(d, 25);
	ASSERT_EQ(d.vo->state(), VoState::Ok);
	const LocalMapView before = d.vo->localMap();
	ASSERT_GE(before.keyframes.size(), 2u);
	ASSERT_GT(before.points.size(), 100u);
	// The anchor is the earliest optimised keyframe.
	for (const auto& k : before.keyframes)
	{
		if (!k.fixed)
		{
			EXPECT_GE(k.id, before.anchor_id);
		}
	}

	const double s = 2.5;
	ASSERT_TRUE(d.vo->rescaleAboutWindow(s));
	const LocalMapView after = d.vo->localMap();
	ASSERT_EQ(after.keyframes.size(), before.keyframes.size());
	ASSERT_EQ(after.points.size(), before.points.size());
	EXPECT_EQ(after.anchor_id, before.anchor_id);
	EXPECT_TRUE(after.anchor_Tcw.isApprox(before.anchor_Tcw, 1e-12));
	const Vec3 a = centre(before.anchor_Tcw);
	for (std::size_t i = 0; i < before.keyframes.size(); ++i)
	{
		const Vec3 c0 = centre(before.keyframes[i].Tcw), c1 = centre(after.keyframes[i].Tcw);
		EXPECT_NEAR((c1 - a).norm(), s * (c0 - a).norm(), 1e-9);
		EXPECT_TRUE(after.keyframes[i].Tcw.linear().isApprox(before.keyframes[i].Tcw.linear(), 1e-12));
	}
	for (std::size_t i = 0; i < before.points.size(); ++i)
	{
		ASSERT_EQ(after.points[i].id, before.points[i].id);
		EXPECT_NEAR((after.points[i].pos - a).norm(), s * (before.points[i].pos - a).norm(), 1e-9);
		// Same bearing from the anchor camera: the scale is about its centre, nothing else moves.
		EXPECT_LT(((after.points[i].pos - a).normalized() - (before.points[i].pos - a).normalized()).norm(), 1e-9);
	}
	// Tracking goes on in the new scale: later motions are s times longer, the output continues.
	const auto prev = d.vo->lastInfo();
	drive(d, 1);
	EXPECT_LT((d.vo->lastInfo().pose->translation() - prev.pose->translation()).norm(),
		1.5 * s * prev.motion->translation().norm());
	drive(d, 2);
	ASSERT_EQ(d.vo->state(), VoState::Ok);
	ASSERT_TRUE(d.vo->lastInfo().motion && prev.motion);
	const double ratio = d.vo->lastInfo().motion->translation().norm() / prev.motion->translation().norm();
	EXPECT_NEAR(ratio, s, 0.15 * s);
}

TEST(ScaleInterface, MapScaleAfterInitialisation)
{
	const auto cam = test::kittiCamera();
	Driven d{std::make_unique<VisualOdometry>(cam, VoOptions()), test::StreetRenderer(test::StreetScene(), cam)};
	EXPECT_FALSE(d.vo->setMapScale(2.0));  // no map yet
	EXPECT_FALSE(d.vo->rescaleAboutWindow(2.0));
	while (!d.vo->lastInfo().new_map && d.k < 10) drive(d, 1);
	ASSERT_TRUE(d.vo->lastInfo().new_map);
	const double unit = d.vo->lastInfo().pose->translation().norm();
	// The true motion per frame is ~1 m; with that metric scale the next motions are ~1 m.
	const long gap = d.vo->localMap().keyframes.back().frame_index - d.vo->localMap().keyframes.front().frame_index;
	ASSERT_TRUE(d.vo->setMapScale(gap * 1.0 / unit));
	drive(d, 5);
	ASSERT_EQ(d.vo->state(), VoState::Ok);
	EXPECT_NEAR(d.vo->lastInfo().motion->translation().norm(), 1.0, 0.1);
}
