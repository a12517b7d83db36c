// The KITTI metric on constructed trajectories whose errors have a closed form.
//
// Set-up shared by the tests: N = 1001 frames, consecutive positions exactly c = 0.9 m apart (the
// devkit's distances are sums of those chords), first frames every 10. A segment of length L
// ends at the first frame strictly beyond L metres, i.e. after n_L = floor(L / c) + 1 steps, so it
// really covers n_L * c metres (the devkit's overshoot), and the first frames that fit are
// f = 0, 10, ..., f <= 1000 - n_L: count_L = floor((1000 - n_L) / 10) + 1 of them.
//
//   L      100    200    300    400    500    600    700    800
//   n_L    112    223    334    445    556    667    778    889
//   count   89     78     67     56     45     34     23     12      (404 segments)
//   n_L c/L 1.008 1.0035 1.002 1.00125 1.0008 1.0005 1.000286 1.000125
//
// Both drifts below make a segment's error proportional to n_L c, so the pooled mean carries
//   F = sum(count_L * n_L c / L) / 404 = 405.25007 / 404 = 1.0030942.
#include <gtest/gtest.h>
#include <vlo/eval/kitti_metric.h>

#include "eval_test_utils.h"

using namespace vlo;
using namespace vlo::eval;
using namespace vlo::test;

namespace
{
constexpr std::size_t N = 1001;
constexpr double c = 0.9;
constexpr double deg = M_PI / 180;

/// sum over segments of w(n_L, L), and the segment count, enumerated as the header explains.
template <class W>
std::pair<double, std::size_t> pooled(W w)
{
	double sum = 0;
	std::size_t count = 0;
	for (double L = 100; L <= 800; L += 100)
	{
		const std::size_t n = static_cast<std::size_t>(std::floor(L / c)) + 1;
		const std::size_t cnt = (N - 1 - n) / 10 + 1;
		sum += cnt * w(n, L);
		count += cnt;
	}
	return {sum, count};
}

const double F = 1.0030942;  // hand value from the header
}  // namespace

TEST(KittiMetric, HandComputedOvershootFactorIsRight)
{
	const auto [sum, count] = pooled([](std::size_t n, double L) { return n * c / L; });
	EXPECT_EQ(count, 404u);
	EXPECT_NEAR(sum / count, F, 1e-7);
}

TEST(KittiMetric, IdenticalTrajectoriesGiveZero)
{
	const Trajectory gt = fromSteps(N, arcStep(c, 0.004));
	const KittiResult r = kittiMetric(gt, gt);
	ASSERT_EQ(r.segments.size(), 404u);
	EXPECT_NEAR(r.t_err, 0, 1e-12);
	EXPECT_NEAR(r.r_err, 0, 1e-9);  // the devkit's acos loses precision near 0: ~1e-8 rad / 100 m
}

TEST(KittiMetric, StraightLineWithConstantScaleError)
{
	// The estimate goes 5 % too far: a segment's error is 0.05 * n_L c metres, t_err = 0.05 * F.
	const Trajectory gt = fromSteps(N, arcStep(c, 0)), est = scaled(gt, 1.05);
	const KittiResult r = kittiMetric(gt, est);
	ASSERT_EQ(r.segments.size(), 404u);
	EXPECT_NEAR(100 * r.t_err, 5.015471, 1e-5);  // 5 % * 1.0030942
	EXPECT_NEAR(r.r_err, 0, 1e-12);
	ASSERT_EQ(r.per_length.size(), 8u);
	EXPECT_EQ(r.per_length[0].n, 89u);
	EXPECT_NEAR(r.per_length[0].t_err, 0.05 * 1.008, 1e-12);  // L = 100: 112 steps = 100.8 m
	EXPECT_NEAR(r.per_length[7].t_err, 0.05 * 1.000125, 1e-12);
}

TEST(KittiMetric, StraightLineWithYawDrift)
{
	// The estimate yaws 0.01 deg per metre driven (eps = 0.009 deg per 0.9 m step) while the ground
	// truth goes straight: a segment's rotation error is n_L * eps, r_err = 0.01 deg/m * F.
	const double eps = 0.01 * deg * c;
	const Trajectory gt = fromSteps(N, arcStep(c, 0));
	const Trajectory est = fromSteps(N, arcStep(c, 0) * makePose(Rz(eps), Eigen::Vector3d::Zero()));
	const KittiResult r = kittiMetric(gt, est);
	ASSERT_EQ(r.segments.size(), 404u);
	EXPECT_NEAR(r.r_err / deg, 0.010030942, 1e-9);
	EXPECT_GT(r.t_err, 0);  // a curving estimate also ends elsewhere
}

TEST(KittiMetric, CurvedPathWithConstantScaleError)
{
	// Circle of radius R = 300 m. With the estimate's positions scaled by 1 + k and orientations
	// kept, the error of a segment is [I, -k R_d^T u] with u the ground truth's displacement, so
	// t_err = k |u| / L where |u| = chord = 2 R sin(n_L dtheta / 2) (e.g. L = 100: 112 steps,
	// arc 100.8 m, chord 100.33 m), and r_err = 0.
	const double R = 300, dtheta = 2 * std::asin(c / (2 * R)), k = 0.03;
	const Trajectory gt = fromSteps(N, arcStep(c, dtheta)), est = scaled(gt, 1 + k);
	const auto [sum, count] = pooled([&](std::size_t n, double L) { return k * 2 * R * std::sin(n * dtheta / 2) / L; });
	const KittiResult r = kittiMetric(gt, est);
	ASSERT_EQ(r.segments.size(), count);
	EXPECT_NEAR(r.t_err, sum / count, 1e-12);
	EXPECT_LT(r.t_err, k);  // chords are shorter than the path
	EXPECT_NEAR(r.r_err, 0, 1e-9);
}

TEST(KittiMetric, CurvedPathWithYawDrift)
{
	// Same circle; the estimate turns eps more per step. All rotations are about z, so a segment's
	// rotation error is exactly n_L * eps and r_err = (eps / c) * F, as on the straight line.
	const double R = 300, dtheta = 2 * std::asin(c / (2 * R)), eps = 0.02 * deg * c;
	const Trajectory gt = fromSteps(N, arcStep(c, dtheta));
	const Trajectory est = fromSteps(N, arcStep(c, dtheta) * makePose(Rz(eps), Eigen::Vector3d::Zero()));
	const KittiResult r = kittiMetric(gt, est);
	EXPECT_NEAR(r.r_err / deg, 0.02 * F, 1e-8);
}

TEST(KittiMetric, ShortTrajectoryHasNoSegments)
{
	const Trajectory gt = fromSteps(100, arcStep(c, 0));  // 89.1 m
	const KittiResult r = kittiMetric(gt, scaled(gt, 1.1));
	EXPECT_TRUE(r.empty());
	EXPECT_TRUE(r.per_length.empty());
	EXPECT_EQ(r.t_err, 0);
}

TEST(KittiMetric, SegmentEndIsStrictlyBeyondTheLength)
{
	// Positions 1 m apart: dist[i] = i exactly, so a 100 m segment from frame 0 ends at frame 101.
	const Trajectory gt = fromSteps(150, arcStep(1.0, 0));
	KittiOptions o;
	o.lengths = {100};
	const KittiResult r = kittiMetric(gt, gt, o);
	ASSERT_FALSE(r.empty());
	EXPECT_EQ(r.segments[0].first, 0u);
	EXPECT_EQ(r.segments[0].last, 101u);
	EXPECT_EQ(r.segments.size(), 5u);  // first frames 0, 10, 20, 30, 40 (48 would need frame 149)
}
