// The devkit's plot curves on the straight drive of test_kitti_metric.cpp (1001 frames 0.9 m apart at
// 10 Hz, 9 m/s): a segment of length L spans n_L + 1 frames (n_L = floor(L / 0.9) + 1), so its speed
// is L / (0.1 (n_L + 1)), between 8.85 m/s (L = 100) and 8.99 m/s (L = 800).
#include <gtest/gtest.h>
#include <vlo/eval/kitti_curves.h>

#include "eval_test_utils.h"

using namespace vlo;
using namespace vlo::eval;
using namespace vlo::test;

namespace
{
constexpr double c = 0.9;
}

TEST(KittiCurves, SegmentSpeedIsTheDevkits)
{
	const Trajectory gt = fromSteps(1001, arcStep(c, 0));
	const KittiResult r = kittiMetric(gt, gt);
	ASSERT_FALSE(r.empty());
	for (const auto& seg : r.segments)
		EXPECT_NEAR(seg.speed, seg.length / (0.1 * double(seg.last - seg.first + 1)), 1e-9);
	EXPECT_NEAR(r.segments.front().speed, 100 / (0.1 * 113), 1e-9);  // L = 100: 112 steps, 113 frames
}

TEST(KittiCurves, ConstantScaleErrorGivesTheKnownCurves)
{
	// 5 % too long: every segment's t_err is 0.05 n_L c / L (test_kitti_metric.cpp), r_err 0.
	const Trajectory gt = fromSteps(1001, arcStep(c, 0)), est = scaled(gt, 1.05);
	const KittiCurves k = kittiCurves(kittiMetric(gt, est));
	ASSERT_EQ(k.by_length.size(), 8u);
	const std::size_t counts[] = {89, 78, 67, 56, 45, 34, 23, 12};
	for (std::size_t i = 0; i < 8; ++i)
	{
		const double L = 100.0 * double(i + 1), n = std::floor(L / c) + 1;
		EXPECT_EQ(k.by_length[i].x, L);
		EXPECT_EQ(k.by_length[i].n, counts[i]);
		EXPECT_NEAR(k.by_length[i].t_err, 0.05 * n * c / L, 1e-12) << L;
		EXPECT_NEAR(k.by_length[i].r_err, 0, 1e-12);
	}
	// Speeds 8.85..8.99 m/s are within 2 m/s of the devkit's points 8 and 10 only: both average all
	// 404 segments, 0.05 times the overshoot factor F = 1.0030942.
	ASSERT_EQ(k.by_speed.size(), 2u);
	EXPECT_EQ(k.by_speed[0].x, 8);
	EXPECT_EQ(k.by_speed[1].x, 10);
	for (const auto& p : k.by_speed)
	{
		EXPECT_EQ(p.n, 404u);
		EXPECT_NEAR(p.t_err, 0.05 * 1.0030942, 1e-7);
	}
}

TEST(KittiCurves, FewerThanThreeSegmentsGiveNoPoint)
{
	// 130 frames, 116.1 m: L = 100 fits from frames 0 and 10 only (112 steps), two segments.
	const Trajectory gt = fromSteps(130, arcStep(c, 0));
	const KittiResult r = kittiMetric(gt, scaled(gt, 1.1));
	ASSERT_EQ(r.segments.size(), 2u);
	EXPECT_TRUE(kittiCurves(r).empty());
}

TEST(KittiCurves, NoTimestampsGiveNoSpeedCurve)
{
	Trajectory gt = fromSteps(1001, arcStep(c, 0));
	for (auto& p : gt) p.t = 0;
	const KittiCurves k = kittiCurves(kittiMetric(gt, scaled(gt, 1.05)));
	EXPECT_EQ(k.by_length.size(), 8u);
	EXPECT_TRUE(k.by_speed.empty());
}
