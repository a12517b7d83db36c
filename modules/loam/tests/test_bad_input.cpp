// Bad input never crashes: the frame is skipped with a reason and the pose follows the prior.
#include <gtest/gtest.h>
#include <vlo/loam/lidar_odometry.h>

#include <limits>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
struct Drive
{
	Path path;
	World world;
	Drive()
	{
		path.add(100, 0.0);
		world = urbanWorld(path, 8);
	}
	Eigen::Isometry3d truth(int i) const { return lidarPoseAt(path, 10.0 + i); }
	PointCloud scanAt(int i) const { return scan(world, vlp16(), truth(i)); }
};

PointCloud singleRing()
{
	PointCloud pc;
	for (int i = 0; i < 1800; ++i)
	{
		const double a = 2 * M_PI * i / 1800;
		pc.push_back(LidarPoint{static_cast<float>(10 * std::cos(a)), static_cast<float>(10 * std::sin(a)), -0.5f, 0});
	}
	return pc;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

TEST(BadInput, SkippedWithAReasonNeverThrown)
{
	const float nan = std::numeric_limits<float>::quiet_NaN();
	const PointCloud empty, all_nan(5000, LidarPoint{nan, nan, nan, 0});
	PointCloud too_close, few;
	for (int i = 0; i < 3000; ++i) too_close.push_back(LidarPoint{0.5f, 0.0001f * i, 0.f, 0});
	for (int i = 0; i < 40; ++i) few.push_back(LidarPoint{10.f, 0.1f * i, -1.f, 0});

	LidarOdometry lo(vlp16Options());
	const struct
	{
		const PointCloud* pc;
		const char* why;
	} cases[] = {{&empty, "no usable points"}, {&all_nan, "5000 invalid"}, {&too_close, "out of range"},
		{nullptr, "populated rings"}, {&few, "populated rings"}};
	const PointCloud ring = singleRing();
	double t = 0;
	for (const auto& c : cases)
	{
		LidarOdometryResult r;
		ASSERT_NO_THROW(r = lo.process(t += 0.1, c.pc ? *c.pc : ring, std::nullopt));
		EXPECT_EQ(r.status, LidarFrameStatus::Skipped);
		EXPECT_TRUE(contains(r.reason, c.why)) << c.why << " / " << r.reason;
		EXPECT_TRUE(r.pose.isApprox(Eigen::Isometry3d::Identity()));
	}
	// Features too few although rings are populated: a sparse scan of a plain.
	World plain;
	LidarOdometryResult r = lo.process(t += 0.1, scan(plain, vlp16(), lidarPoseAt(Path(), 0)), std::nullopt);
	EXPECT_EQ(r.status, LidarFrameStatus::Skipped);
	EXPECT_TRUE(contains(r.reason, "too few") || contains(r.reason, "rings")) << r.reason;
	EXPECT_TRUE(lo.mapPoints().empty());
}

// vlo-run computes a scan's features ahead on the reader's thread (ScanFeatureExtractor) and hands
// them to process: the same poses to the bit as from the scan, bad frames included.
TEST(BadInput, FeaturesComputedAheadGiveTheSamePoses)
{
	const Drive d;
	LidarOdometry from_scans(vlp16Options()), from_features(vlp16Options());
	ScanFeatureExtractor ahead(vlp16Options());
	for (int i = 0; i <= 8; ++i)
	{
		const PointCloud scan = i == 3 ? PointCloud() : d.scanAt(i);
		const double t = 0.1 * i;
		const LidarOdometryResult a = from_scans.process(t, scan, std::nullopt);
		const LidarOdometryResult b = from_features.process(t, ahead.extract(scan), std::nullopt);
		EXPECT_EQ(a.status, b.status) << "frame " << i;
		EXPECT_EQ(a.reason, b.reason);
		EXPECT_EQ(a.n_valid, b.n_valid);
		EXPECT_EQ(a.pose.matrix(), b.pose.matrix()) << "frame " << i;
	}
	EXPECT_EQ(from_scans.mapPoints(), from_features.mapPoints());
}

TEST(BadInput, TrackingResumesAfterBadFrames)
{
	const Drive d;
	LidarOdometry lo(vlp16Options());
	// A bad first frame: the next good one starts the map at the prior's (identity) pose.
	EXPECT_EQ(lo.process(0.0, PointCloud(), std::nullopt).status, LidarFrameStatus::Skipped);
	EXPECT_EQ(lo.process(0.1, d.scanAt(0), std::nullopt).status, LidarFrameStatus::Initialized);
	const Eigen::Isometry3d T0 = d.truth(0);
	for (int i = 1; i <= 4; ++i) EXPECT_EQ(lo.process(0.1 + 0.1 * i, d.scanAt(i), std::nullopt).status, LidarFrameStatus::Ok);

	// A dropout in the middle: the pose moves on at constant velocity, then tracking resumes.
	const LidarOdometryResult prev = lo.process(0.6, d.scanAt(5), std::nullopt);
	const LidarOdometryResult gap = lo.process(0.7, PointCloud(), std::nullopt);
	EXPECT_EQ(gap.status, LidarFrameStatus::Skipped);
	EXPECT_TRUE(gap.pose.isApprox(prev.pose * gap.guess, 1e-9));
	EXPECT_LT(translationError(gap.pose, T0.inverse() * d.truth(6)), 0.1);  // steady speed
	for (int i = 7; i <= 9; ++i)
	{
		const LidarOdometryResult r = lo.process(0.1 + 0.1 * i, d.scanAt(i), std::nullopt);
		EXPECT_EQ(r.status, LidarFrameStatus::Ok) << r.reason;
		EXPECT_LT(translationError(r.pose, T0.inverse() * d.truth(i)), 0.05);
	}
}

TEST(BadInput, NonsenseExternalMotionFallsBack)
{
	const Drive d;
	LoamOptions o = vlp16Options();
	o.prior.source = "external";
	LidarOdometry lo(o);
	Eigen::Isometry3d nan = Eigen::Isometry3d::Identity();
	nan.translation().x() = std::numeric_limits<double>::quiet_NaN();
	const Eigen::Isometry3d T0 = d.truth(0);
	for (int i = 0; i < 4; ++i)
	{
		const LidarOdometryResult r = lo.process(0.1 * i, d.scanAt(i), nan);
		if (i > 0)
		{
			EXPECT_EQ(r.prior_source, i == 1 ? "cold_start" : "constant_velocity");  // the first motion is searched
		}
		EXPECT_LT(translationError(r.pose, T0.inverse() * d.truth(i)), 0.05);
	}
}
}  // namespace vlo::loam::test

namespace vlo::loam::test
{
TEST(BadInput, AnExternalGuessThatFitsTheMapWorseIsSetAside)
{
	// 1 m per frame; at frame 4 the external motion is 0.4 m off sideways and 1 deg (within the prior's
	// 0.5 m deviation bound, so it is accepted): against the map the constant-velocity guess fits
	// better and LOAM starts from it. Without the check (check_deviation = 0) the external guess is used.
	const Drive d;
	for (const double check : {0.05, 0.0})
	{
		LoamOptions o = vlp16Options();
		o.prior.source = "external";
		o.prior.check_deviation = check;
		LidarOdometry lo(o);
		const Eigen::Isometry3d T0 = d.truth(0);
		for (int i = 0; i < 5; ++i)
		{
			Eigen::Isometry3d step = d.truth(i - 1).inverse() * d.truth(i);
			if (i == 4) step = step * planarPose(0.0, 0.4, 1.0);
			const LidarOdometryResult r = lo.process(0.1 * i, d.scanAt(i), step);
			if (i < 4) continue;
			if (check > 0)
			{
				EXPECT_EQ(r.prior_source, "constant_velocity (external fits the map worse)");
				EXPECT_GT(r.guess_fit_constant_velocity, 1.05 * r.guess_fit_external);
			}
			else
			{
				EXPECT_EQ(r.prior_source, "external");
				EXPECT_EQ(r.guess_fit_external, 0.0);
			}
			EXPECT_LT(translationError(r.pose, T0.inverse() * d.truth(i)), 0.05);
		}
	}
}
}  // namespace vlo::loam::test
