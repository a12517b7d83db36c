// Deskew of synthetically skewed sweeps: each point captured in the sensor frame of its own instant
// under a constant-velocity motion, then moved back into the frame's sensor frame.
#include <gtest/gtest.h>
#include <vlo/core/se3_twist.h>
#include <vlo/core/sweep_times.h>
#include <vlo/icp/deskew.h>

#include <algorithm>
#include <cmath>

#include "scene.h"

namespace vlo::icp::test
{
namespace
{
// 12 m/s forward and 4 deg per 0.1 s frame: up to 0.6 m and 2 deg of skew at the sweep's ends.
const Eigen::Isometry3d kMotion = motion(1.2, 0.05, 0.0, 4.0, 0.3, 0.0);
constexpr double kDt = 0.1;

// The true scan (sensor frame at the frame time) and its skewed capture: a point fired at time tau
// lies in the sensor frame of t + tau, which is exp(tau / dt log(kMotion)) in the frame's own.
struct Skewed
{
	Points truth;
	PointCloud scan;
};

Skewed skewedSweep(bool with_times)
{
	Skewed s;
	const PointCloud straight = scanFrom(streetScene(20000, 9), Eigen::Isometry3d::Identity());
	for (const auto& p : straight)
	{
		const double tau = SpinningSweep{}.timeAt(std::atan2(p.y, p.x));  // KISS-ICP's rule, KITTI's sweep
		const Eigen::Vector3d v = expTwist(tau / kDt * logTwist(kMotion)).inverse() * Eigen::Vector3d(p.x, p.y, p.z);
		s.truth.emplace_back(p.x, p.y, p.z);
		s.scan.push_back(LidarPoint{float(v.x()), float(v.y()), float(v.z()), 0.f, float(tau)});
	}
	s.scan.has_time = with_times;
	return s;
}

double maxError(const Points& a, const Points& b)
{
	double e = 0;
	for (std::size_t i = 0; i < a.size(); ++i) e = std::max(e, (a[i] - b[i]).norm());
	return e;
}
}  // namespace

// The constant twist the deskew follows: the fraction s of kMotion, for s in and beyond [0, 1].
TEST(Deskew, ConstantTwistInterpolatesAndExtrapolates)
{
	const auto part = [](double s) { return expTwist(s * logTwist(kMotion)); };
	EXPECT_TRUE(part(1.0).isApprox(kMotion, 1e-12));
	EXPECT_TRUE(part(0.0).isApprox(Eigen::Isometry3d::Identity()));
	EXPECT_TRUE((part(0.5) * part(0.5)).isApprox(kMotion, 1e-12));
	EXPECT_TRUE((part(-0.25) * part(1.25)).isApprox(kMotion, 1e-12));
	EXPECT_NEAR(rotationDeg(part(-0.5)), 0.5 * rotationDeg(kMotion), 1e-9);
}

TEST(Deskew, PerPointTimesUndoTheSkewExactly)
{
	const Skewed s = skewedSweep(true);
	const Points raw = deskewExact(skewedSweep(false).scan, kMotion, kDt);
	EXPECT_GT(maxError(raw, s.truth), 0.5);  // what is at stake: a scan without times is taken as it is
	EXPECT_LT(maxError(deskewExact(s.scan, kMotion, kDt), s.truth), 1e-4);  // float storage
}

TEST(Deskew, AzimuthTimesUndoTheSkewToMillimetres)
{
	// Without times the azimuth of the skewed point stands for that of its firing: the sensor turned by at
	// most 2 deg meanwhile, which shifts the time by up to 2/360 of a sweep (0.6 ms: 7 mm at 12 m/s, and
	// 0.02 deg of rotation: 14 mm at 40 m), more for near points
	// whose azimuth the translation moves. Points within those 2 deg of the seam behind the sensor land
	// at the other end of the sweep: the 99th percentile leaves them out.
	const Skewed s = skewedSweep(false);
	PointCloud timed = s.scan;
	setTimesFromAzimuth(timed, SpinningSweep{});
	const Points fixed = deskewExact(timed, kMotion, kDt);
	std::vector<double> err;
	for (std::size_t i = 0; i < fixed.size(); ++i) err.push_back((fixed[i] - s.truth[i]).norm());
	std::sort(err.begin(), err.end());
	EXPECT_LT(err[err.size() / 2], 0.005);
	EXPECT_LT(err[err.size() * 99 / 100], 0.05);
	const Points raw = deskewExact(s.scan, kMotion, kDt);
	std::vector<double> rawErr;
	for (std::size_t i = 0; i < raw.size(); ++i) rawErr.push_back((raw[i] - s.truth[i]).norm());
	std::sort(rawErr.begin(), rawErr.end());
	EXPECT_GT(rawErr[rawErr.size() / 2], 0.1);
}
}  // namespace vlo::icp::test
