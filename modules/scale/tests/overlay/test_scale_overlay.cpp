// The snapshot overlay: one ring per keypoint in its stage's colour, tracks, a legend with counts.
#include <gtest/gtest.h>
#include <vlo/scale/overlay.h>

using namespace vlo;
using namespace vlo::scale;

TEST(ScaleOverlay, ColoursByRejectingStageWithCountsInTheLegend)
{
	ScaleEstimate e;
	auto add = [&](Stage s, float x) {
		KeypointDiag d;
		d.prev = {x, 10}, d.cur = {x + 2, 11}, d.rejected_by = s;
		e.keypoints.push_back(d);
	};
	add(Stage::None, 10), add(Stage::None, 20), add(Stage::Epipolar, 30), add(Stage::Tracking, 40);
	EXPECT_EQ(scaleOverlay(e).legend[0].first, "kept 2");  // RANSAC never ran: survivors, not inliers
	e.counts.inliers = 2;
	const viz::ImageOverlay o = scaleOverlay(e);
	ASSERT_EQ(o.points.size(), 4u);
	EXPECT_EQ(o.segments.size(), 3u);  // a lost keypoint has no track
	// Inliers are drawn last (on top).
	EXPECT_TRUE(o.points.back().color == stageColor(Stage::None));
	ASSERT_EQ(o.legend.size(), 3u);
	EXPECT_EQ(o.legend[0].first, "inlier 2");
	EXPECT_EQ(o.legend[1].first, "off epipolar line 1");
	EXPECT_EQ(o.legend[2].first, "track lost 1");
	EXPECT_TRUE(o.legend[1].second == stageColor(Stage::Epipolar));
	// Every stage has its own colour.
	const Stage all[] = {Stage::None, Stage::Tracking, Stage::Epipolar, Stage::Gradient, Stage::Triangulation, Stage::Ransac};
	for (Stage a : all)
		for (Stage b : all)
		{
			if (a == b) continue;
			EXPECT_FALSE(stageColor(a) == stageColor(b));
		}
	EXPECT_TRUE(scaleOverlay(e, false).segments.empty());
}
