#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/eval/association.h>

#include "eval_test_utils.h"

using namespace vlo;
using namespace vlo::eval;
using namespace vlo::test;

namespace
{
/// Moves at 1 m/s along x while turning at 0.1 rad/s: the exact pose at any time t.
Eigen::Isometry3d truth(double t) { return makePose(Rz(0.1 * t), Eigen::Vector3d(t, 0, 0)); }

Trajectory sampled(double t0, double t1, double dt)
{
	Trajectory tr;
	for (int i = 0; t0 + i * dt <= t1 + 1e-9; ++i) tr.push_back({t0 + i * dt, truth(t0 + i * dt)});
	return tr;
}
}  // namespace

TEST(Association, SlowGroundTruthIsInterpolatedAtEveryEstimate)
{
	// 1 Hz ground truth, 10 Hz estimate over the same 10 s: every estimate matches, and because the
	// motion is linear in position and a constant-axis rotation, interpolation is exact.
	const Trajectory gt = sampled(0, 10, 1.0), est = sampled(0, 10, 0.1);
	const Association a = associate(gt, est);
	ASSERT_EQ(a.matched(), est.size());
	EXPECT_EQ(a.n_outside_span, 0u);
	EXPECT_NEAR(a.max_gap_used_s, 3.0, 1e-9);  // 3x the median 1 s spacing
	for (std::size_t i = 0; i < a.matched(); ++i)
	{
		EXPECT_DOUBLE_EQ(a.gt[i].t, a.est[i].t);
		EXPECT_TRUE(a.gt[i].pose.isApprox(a.est[i].pose, 1e-12)) << "t = " << a.est[i].t;
	}
}

TEST(Association, DropsEstimatesOutsideTheGroundTruthSpan)
{
	const Trajectory gt = sampled(2, 8, 1.0), est = sampled(0, 10, 0.1);
	const Association a = associate(gt, est);
	EXPECT_EQ(a.matched(), 61u);  // 2.0, 2.1, ..., 8.0
	EXPECT_EQ(a.n_outside_span, 40u);
	EXPECT_NEAR(a.est.front().t, 2.0, 1e-9);
	EXPECT_NEAR(a.est.back().t, 8.0, 1e-9);
}

TEST(Association, ToleratesTinyTimestampRoundingAtTheEnds)
{
	const Trajectory gt = sampled(0, 5, 1.0);
	Trajectory est = sampled(0, 5, 0.5);
	est.front().t -= 1e-8;
	est.back().t += 1e-8;
	EXPECT_EQ(associate(gt, est).matched(), est.size());
}

TEST(Association, DoesNotInterpolateAcrossWideGaps)
{
	Trajectory gt = sampled(0, 10, 1.0);
	gt.erase(gt.begin() + 4, gt.begin() + 7);  // samples 4, 5, 6 missing: a 4 s gap from 3 to 7
	const Trajectory est = sampled(0, 10, 0.1);
	AssociationOptions o;
	o.max_gap_s = 1.5;
	const Association a = associate(gt, est, o);
	EXPECT_EQ(a.n_in_gap, 39u);  // 3.1 ... 6.9
	EXPECT_EQ(a.matched(), est.size() - 39);
	o.max_gap_s = 5;
	EXPECT_EQ(associate(gt, est, o).matched(), est.size());
}

TEST(Association, NoOverlapGivesAnEmptyResult)
{
	const Association a = associate(sampled(0, 5, 1.0), sampled(10, 20, 0.1));
	EXPECT_EQ(a.matched(), 0u);
	EXPECT_EQ(a.n_outside_span, a.n_est);
}

TEST(Association, RejectsTimestampsOutOfOrder)
{
	Trajectory gt = sampled(0, 5, 1.0);
	std::swap(gt[1], gt[2]);
	EXPECT_THROW(associate(gt, sampled(0, 5, 0.1)), InputError);
}
