// A revisit the other way round in the other lane of a road (3.5 m to the side): from the keyframe's
// own viewpoint the descriptor's guess (the candidate's position, turned) is 3.5 m off, beyond the
// registration's coarse gate; the viewpoint shifted by query_shift finds the candidate and starts the
// registration next to the truth.
#include <gtest/gtest.h>
#include <vlo/loop/place_recognition.h>
#include <vlo/loop/verification.h>

#include "synthetic_places.h"

#include <cstdio>

using namespace vlo;
using namespace vlo::loop;
using namespace vlo::loop::test;

namespace
{
constexpr double kLane = 3.5, kDeg = M_PI / 180;

struct Revisit
{
	std::optional<PlaceCandidate> candidate;
	Verification verification;
	Eigen::Isometry3d truth;  ///< candidate_T_current
};

ScanPoints keyframeAt(const World& world, const Eigen::Isometry3d& pose, std::mt19937& rng)
{
	return keyframeScan(scanFrom(world, pose, rng), Eigen::Isometry3d::Identity(), 0.1, Eigen::Isometry3d::Identity(), 0.5);
}

/// Out along +x in the right lane (y = -1.75), a keyframe every 2 m; back along -x in the other lane,
/// one keyframe at x = 10.6 queried and its candidate verified, the odometry 1.2 m off.
Revisit backInTheOtherLane(double query_shift)
{
	const World world = randomCity(5, -120, 120, -90, 90, 150, [](const Eigen::Vector2d& lo, const Eigen::Vector2d& size) {
		return lo.y() < 7 && lo.y() + size.y() > -7;
	});
	std::mt19937 rng(3);
	LoopOptions options;
	options.query_shift = query_shift;
	PlaceRecognitionParams params;
	params.query_shift = query_shift;
	PlaceDatabase places(params);
	std::vector<Keyframe> out;
	for (int k = 0; k <= 40; ++k)
	{
		Keyframe kf;
		kf.odometry = pose2d(-40 + 2 * k, -kLane / 2, 0);
		kf.path = 2 * k;
		kf.points = keyframeAt(world, kf.odometry, rng);
		EXPECT_FALSE(places.addAndQuery(kf.points, kf.path).has_value());  // nothing 50 m behind yet
		out.push_back(std::move(kf));
	}
	Revisit r;
	const Eigen::Isometry3d back = pose2d(10.6, kLane / 2, M_PI + 2 * kDeg);
	const ScanPoints current = keyframeAt(world, back, rng);
	r.candidate = places.addAndQuery(current, 300);
	if (!r.candidate) return r;
	const Keyframe& earlier = out[r.candidate->keyframe];
	r.truth = earlier.odometry.inverse() * back;
	const Eigen::Isometry3d odometry = r.truth * pose2d(1.0, 0.7, 0);
	r.verification = verifyLoop(current, candidateSubmap(out, r.candidate->keyframe, 5, out.size()), r.candidate->match,
		odometry, 300 - earlier.path, options);
	const LoopRecord& l = r.verification.record;
	std::printf("query_shift %.1f: candidate x %.0f, descriptor %.3f, yaw %.0f deg, viewpoint %.1f m; inliers %.2f, "
				"registration error %.3f m; %s\n",
		query_shift, earlier.odometry.translation().x(), r.candidate->match.distance, l.yaw_deg, r.candidate->match.viewpoint_y,
		l.inlier_fraction, (l.candidate_T_current.translation() - r.truth.translation()).norm(),
		l.accepted ? "accepted" : l.reason.c_str());
	return r;
}
}  // namespace

TEST(LaneRevisit, TheOtherWayInTheOtherLaneIsFoundFromAShiftedViewpoint)
{
	const Revisit on = backInTheOtherLane(kLane);
	ASSERT_TRUE(on.candidate.has_value());
	// The other lane is to the left of the way back: the viewpoint 3.5 m to the left matched best.
	EXPECT_EQ(on.candidate->match.viewpoint_y, kLane);
	EXPECT_NEAR(std::abs(on.candidate->match.yaw), M_PI, 6 * kDeg);
	const LoopRecord& l = on.verification.record;
	EXPECT_TRUE(l.accepted) << l.reason;
	EXPECT_LT((l.candidate_T_current.translation() - on.truth.translation()).norm(), 0.03);
	EXPECT_LT(Eigen::AngleAxisd(l.candidate_T_current.linear().transpose() * on.truth.linear()).angle(), 0.2 * kDeg);
}

TEST(LaneRevisit, FromItsOwnViewpointTheRegistrationMissesIt)
{
	const Revisit off = backInTheOtherLane(0);
	// The descriptor finds the place, but the registration from the candidate's position slides to a
	// wrong pose and fails a gate.
	ASSERT_TRUE(off.candidate.has_value());
	const LoopRecord& l = off.verification.record;
	EXPECT_FALSE(l.accepted);
	EXPECT_GT((l.candidate_T_current.translation() - off.truth.translation()).norm(), 1.0);
}
