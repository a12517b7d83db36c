// A whole unscaled path moved onto the ground truth, as the snapshots of mode vo draw it.
#include "eval_test_utils.h"

#include <gtest/gtest.h>
#include <vlo/eval/trajectory_alignment.h>

using namespace vlo;
using namespace vlo::eval;
using namespace vlo::test;

TEST(TrajectoryAlignment, UnscaledPathLandsOnTheGroundTruth)
{
	const Trajectory gt = fromSteps(20, arcStep(1.0, 0.05));
	const Trajectory est = scaled(gt, 0.25);
	const auto S = sim3ToGroundTruth(gt, est);
	ASSERT_TRUE(S.has_value());
	EXPECT_NEAR(S->s, 4.0, 1e-9);
	const Trajectory aligned = transformed(est, *S);
	ASSERT_EQ(aligned.size(), gt.size());
	for (std::size_t i = 0; i < gt.size(); ++i)
	{
		EXPECT_LT((aligned[i].pose.translation() - gt[i].pose.translation()).norm(), 1e-9);
		EXPECT_TRUE(aligned[i].pose.linear().isApprox(gt[i].pose.linear(), 1e-9));  // rotation only, no scale
	}
}

TEST(TrajectoryAlignment, NoFitWithFewerThanThreePairs)
{
	const Trajectory gt = fromSteps(2, arcStep(1.0, 0.0));
	EXPECT_FALSE(sim3ToGroundTruth(gt, gt).has_value());
}
