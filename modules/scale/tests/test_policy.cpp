// ScaleCorrectionPolicy: the first estimate sets the metric scale, later ones correct beyond 2 %.
#include <gtest/gtest.h>
#include <vlo/scale/policy.h>

#include <vector>

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
	ScaleOptions opt;
	opt.correction_window = 1;  // the paper: each estimate alone
	ScaleCorrectionPolicy p(opt);
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
	opt.correction_window = 1;
	ScaleCorrectionPolicy p(opt);
	p.decide(estimate(1));
	EXPECT_FALSE(p.decide(estimate(1.04)).apply());
	EXPECT_TRUE(p.decide(estimate(1.06)).apply());
}

ScaleCorrectionPolicy windowOf5()
{
	ScaleOptions opt;
	opt.correction_window = 5;
	return ScaleCorrectionPolicy(opt);
}

TEST(Policy, TheMedianOfTheWindowDecidesAndStartsAfreshAfterACorrection)
{
	ScaleCorrectionPolicy p = windowOf5();
	EXPECT_EQ(p.decide(estimate(7.0)).kind, ScaleDecision::Kind::Initial);
	// Scattered estimates around 1: single ones beyond 2 % never trigger a correction.
	for (double s : {1.03, 0.97, 1.01, 0.98, 1.04, 0.99, 1.01}) EXPECT_FALSE(p.decide(estimate(s)).apply()) << s;
	// A real drift (the VO now 5 % short): once it is the median of the last five, it is corrected.
	EXPECT_FALSE(p.decide(estimate(1.05)).apply());  // 0.98 0.99 1.01 1.04 1.05: median 1.01
	const ScaleDecision d = p.decide(estimate(1.05));  // 0.99 1.01 1.04 1.05 1.05: median 1.04
	EXPECT_EQ(d.kind, ScaleDecision::Kind::Correction);
	EXPECT_DOUBLE_EQ(d.factor, 1.04);
}

TEST(Policy, MedianCorrectionValueIgnoresOutliers)
{
	ScaleCorrectionPolicy p = windowOf5();
	p.decide(estimate(1.0));
	for (double s : {1.05, 0.5, 1.04, 1.07}) EXPECT_FALSE(p.decide(estimate(s)).apply());
	const ScaleDecision d = p.decide(estimate(1.2));
	EXPECT_EQ(d.kind, ScaleDecision::Kind::Correction);
	EXPECT_DOUBLE_EQ(d.factor, 1.05);  // median of 0.5 1.04 1.05 1.07 1.2
	// After a correction the window starts again: four more estimates are only collected.
	for (double s : {1.1, 1.1, 1.1, 1.1}) EXPECT_FALSE(p.decide(estimate(s)).apply());
	EXPECT_TRUE(p.decide(estimate(1.1)).apply());
	EXPECT_NEAR(p.cumulative(), 1.0 * 1.05 * 1.1, 1e-12);
	EXPECT_EQ(p.corrections(), 2);
}

// The first full window after the initial estimate refines it with its own, finer threshold; later
// windows use correction_threshold again, and a new map (reset) refines afresh.
TEST(Policy, TheFirstWindowRefinesTheInitialScaleMoreFinely)
{
	ScaleOptions opt;
	opt.correction_window = 3;
	opt.initial_refine_threshold = 0.005;
	ScaleCorrectionPolicy p(opt);
	EXPECT_EQ(p.decide(estimate(20.0)).kind, ScaleDecision::Kind::Initial);
	EXPECT_FALSE(p.decide(estimate(0.990)).apply());
	EXPECT_FALSE(p.decide(estimate(0.995)).apply());
	const ScaleDecision d = p.decide(estimate(0.992));  // median 0.992: 0.8 % off, beyond 0.5 %
	EXPECT_EQ(d.kind, ScaleDecision::Kind::Correction);
	EXPECT_DOUBLE_EQ(d.factor, 0.992);
	for (double s : {0.99, 0.99, 0.99}) EXPECT_FALSE(p.decide(estimate(s)).apply()) << s;  // 1 % < 2 %
	p.reset();
	p.decide(estimate(20.0));
	for (double s : {1.01, 1.01}) EXPECT_FALSE(p.decide(estimate(s)).apply());
	EXPECT_TRUE(p.decide(estimate(1.01)).apply());
	// Off (0): the first window waits for correction_threshold like every other.
	opt.initial_refine_threshold = 0;
	ScaleCorrectionPolicy off(opt);
	off.decide(estimate(20.0));
	for (double s : {0.99, 0.99, 0.99}) EXPECT_FALSE(off.decide(estimate(s)).apply()) << s;
}

// While the first window fills, five estimates that agree the initial scale is off correct it at once;
// scattered ones, or initial_refine_sigmas = 0, wait for the full window.
TEST(Policy, TheFirstWindowCorrectsEarlyWhenItsEstimatesAgree)
{
	ScaleOptions opt;
	opt.correction_window = 15;
	opt.initial_refine_threshold = 0.005;
	const std::vector<double> agree = {1.03, 1.04, 1.035, 1.045, 1.04};  // median 1.04, sigma ~1 %
	const std::vector<double> scattered = {1.04, 0.97, 1.07, 0.95, 1.04};  // median 1.04, sigma ~4.4 %
	auto decisionsUntil = [&](const std::vector<double>& estimates, ScaleCorrectionPolicy& p) {
		p.decide(estimate(20.0));
		int n = 0;
		for (double s : estimates)
		{
			++n;
			if (p.decide(estimate(s)).apply()) return n;
		}
		return 0;
	};
	ScaleCorrectionPolicy sure(opt);
	EXPECT_EQ(decisionsUntil(agree, sure), 5);  // 4 % off, 2 standard errors are 1.1 %
	EXPECT_NEAR(sure.cumulative(), 20.0 * 1.04, 1e-9);
	// The first window starts again on the corrected map: still refining at 0.5 %, early again.
	for (double s : {1.02, 1.02, 1.02, 1.02}) EXPECT_FALSE(sure.decide(estimate(s)).apply());
	EXPECT_TRUE(sure.decide(estimate(1.02)).apply());  // 2 standard errors of 1 % scatter: 1.1 %

	ScaleCorrectionPolicy unsure(opt);
	EXPECT_EQ(decisionsUntil(scattered, unsure), 0);  // 2 standard errors are 4.9 %
	opt.initial_refine_sigmas = 0;
	ScaleCorrectionPolicy waits(opt);
	EXPECT_EQ(decisionsUntil(agree, waits), 0);
}
