// Verification of one candidate against its submap: a true revisit is registered to the truth and
// accepted; a repeated place one facade further is registered perfectly and rejected for its drift.
#include <gtest/gtest.h>
#include <vlo/loop/verification.h>

#include <Eigen/Eigenvalues>

#include "synthetic_places.h"

using namespace vlo;
using namespace vlo::loop;
using namespace vlo::loop::test;

namespace
{
struct Scene
{
	std::vector<Keyframe> keyframes;  // at x = -10, -8, ..., 10, the candidate (index 5) at x = 0
	icp::Points submap;
};

ScanPoints keyframeAt(const World& world, const Eigen::Isometry3d& pose, std::mt19937& rng)
{
	return keyframeScan(scanFrom(world, pose, rng), Eigen::Isometry3d::Identity(), 0.1, Eigen::Isometry3d::Identity(), 0.5);
}

Scene candidateScene(const World& world, std::mt19937& rng)
{
	Scene s;
	for (int k = 0; k <= 10; ++k)
	{
		Keyframe kf;
		kf.odometry = pose2d(-10 + 2 * k, 0, 0);
		kf.points = keyframeAt(world, kf.odometry, rng);
		s.keyframes.push_back(std::move(kf));
	}
	s.submap = candidateSubmap(s.keyframes, 5, 5, s.keyframes.size());
	return s;
}
}  // namespace

TEST(Verification, RegistersATrueRevisitToTheTruth)
{
	const World world = randomCity(21, -100, 100, -100, 100, 100, [](const Eigen::Vector2d& lo, const Eigen::Vector2d& size) {
		return lo.y() < 6 && lo.y() + size.y() > -6;
	});
	std::mt19937 rng(1);
	const Scene scene = candidateScene(world, rng);
	// Back 1 m further on, 1.5 m to the left, turned by 8 deg; the odometry drifted 1.2 m.
	const Eigen::Isometry3d truth = pose2d(1.0, 1.5, 8 * M_PI / 180);
	const ScanPoints current = keyframeAt(world, truth, rng);
	DescriptorMatch match;
	match.distance = 0.1;
	match.yaw = 6 * M_PI / 180;  // the descriptor's sector
	const Verification v = verifyLoop(current, scene.submap, match, pose2d(2.0, 2.2, 9 * M_PI / 180), 300, LoopOptions{});
	const LoopRecord& r = v.record;
	std::printf("inliers %.3f rms %.3f constraint %.3f drift %.3f %s\n", r.inlier_fraction, r.rms, r.constraint, r.drift,
		r.reason.c_str());
	EXPECT_TRUE(r.accepted) << r.reason;
	EXPECT_GT(r.inlier_fraction, 0.9);
	EXPECT_LT((r.candidate_T_current.translation() - truth.translation()).norm(), 0.02);
	EXPECT_LT(Eigen::AngleAxisd(r.candidate_T_current.linear().transpose() * truth.linear()).angle(), 0.1 * M_PI / 180);
	EXPECT_NEAR(r.drift, (Eigen::Vector3d(2.0, 2.2, 0) - truth.translation()).norm(), 0.02);
	// The loop edge's information is positive definite.
	EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix6d>(v.information).eigenvalues()(0), 0.0);
}

TEST(Verification, RejectsTheNextIdenticalFacadeForItsDrift)
{
	const World world = facadeStreet(-150, 150, 12);
	std::mt19937 rng(2);
	const Scene scene = candidateScene(world, rng);
	// One period further: the same view. The odometry knows it is 12 m on, after 20 m of path.
	const ScanPoints current = keyframeAt(world, pose2d(12, 0, 0), rng);
	const Verification v = verifyLoop(current, scene.submap, DescriptorMatch{0.01, 0, 0}, pose2d(12, 0, 0), 20, LoopOptions{});
	const LoopRecord& r = v.record;
	std::printf("inliers %.3f constraint %.3f drift %.3f %s\n", r.inlier_fraction, r.constraint, r.drift, r.reason.c_str());
	EXPECT_FALSE(r.accepted);
	EXPECT_GT(r.inlier_fraction, 0.9);  // it looks the same ...
	EXPECT_NEAR(r.drift, 12.0, 0.1);  // ... but the odometry cannot be 12 m off after 20 m
	EXPECT_EQ(r.reason.rfind("drift too large", 0), 0u);
	// Farther than the gate plus what a registration reaches: rejected without registering.
	const auto far = rejectOutOfReach(DescriptorMatch{0.01, 0, 0}, pose2d(60, 0, 0), 60, LoopOptions{});
	ASSERT_TRUE(far.has_value());
	EXPECT_EQ(far->record.reason.rfind("drift too large", 0), 0u);
	EXPECT_FALSE(rejectOutOfReach(DescriptorMatch{0.01, 0, 0}, pose2d(12, 0, 0), 20, LoopOptions{}).has_value());
}
