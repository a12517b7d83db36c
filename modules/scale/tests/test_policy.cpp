// ScaleCorrectionPolicy: the first estimate sets the metric scale, later ones correct beyond 2 %.
#include <gtest/gtest.h>
#include <vlo/scale/policy.h>

using namespace vlo::scale;

namespace
{
ScaleEstimate estimate(double s, bool valid = true)
{
	ScaleEstimate e;
	e.valid = valid;
	e.reason = valid ? Reason::Ok : Reason::FewInliers;
	e.scale = s;
	return e;
}
}  // namespace

TEST(Policy, InitialThenOnlyBeyondTheThreshold)
{
	ScaleCorrectionPolicy p;
	EXPECT_FALSE(p.decide(estimate(3.1, false)).apply());  // nothing before a valid estimate
	EXPECT_FALSE(p.hasMetricScale());

	const ScaleDecision first = p.decide(estimate(1.005));  // even a tiny one: it defines the scale
	EXPECT_EQ(first.kind, ScaleDecision::Kind::Initial);
	EXPECT_EQ(first.factor, 1.005);
	EXPECT_TRUE(p.hasMetricScale());

	EXPECT_FALSE(p.decide(estimate(1.019)).apply());
	EXPECT_FALSE(p.decide(estimate(0.981)).apply());
	const ScaleDecision up = p.decide(estimate(1.02));
	EXPECT_EQ(up.kind, ScaleDecision::Kind::Correction);
	EXPECT_EQ(up.factor, 1.02);
	EXPECT_EQ(p.decide(estimate(0.95)).kind, ScaleDecision::Kind::Correction);
	EXPECT_FALSE(p.decide(estimate(0.5, false)).apply());
	EXPECT_EQ(p.corrections(), 2);
	EXPECT_NEAR(p.cumulative(), 1.005 * 1.02 * 0.95, 1e-12);

	p.reset();  // VO re-initialised: the next estimate is initial again
	EXPECT_EQ(p.decide(estimate(1.001)).kind, ScaleDecision::Kind::Initial);
	EXPECT_EQ(p.cumulative(), 1.001);
}

TEST(Policy, CorrectionOffKeepsOnlyTheInitialScale)
{
	ScaleOptions opt;
	opt.correction_enabled = false;
	ScaleCorrectionPolicy p(opt);
	EXPECT_EQ(p.decide(estimate(2.0)).kind, ScaleDecision::Kind::Initial);
	EXPECT_FALSE(p.decide(estimate(1.5)).apply());
	EXPECT_EQ(p.cumulative(), 2.0);
}

TEST(Policy, ThresholdIsAnOption)
{
	ScaleOptions opt;
	opt.correction_threshold = 0.05;
	ScaleCorrectionPolicy p(opt);
	p.decide(estimate(1));
	EXPECT_FALSE(p.decide(estimate(1.04)).apply());
	EXPECT_TRUE(p.decide(estimate(1.06)).apply());
}
