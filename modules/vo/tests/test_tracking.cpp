// Tracking on a rendered street: Sim(3) ATE under a bound; a blank stretch of images gives LOST,
// a new map afterwards, and a trajectory that goes on.
#include <gtest/gtest.h>

#include "vo_test_util.h"

using namespace vlo;
using namespace vlo::vo;

TEST(Tracking, StreetDriveWithinSim3Bound)
{
	const auto cam = test::kittiCamera();
	const auto run = test::runStreet(cam, 60, VoOptions());
	// Initialises within the first few frames and then never loses track.
	int first = -1;
	for (const auto& i : run.infos)
		if (i.pose)
		{
			first = static_cast<int>(i.index);
			break;
		}
	ASSERT_GE(first, 0);
	EXPECT_LE(first, 5) << run.infos[0].reason;
	EXPECT_EQ(run.tracked, 60 - first);
	EXPECT_EQ(run.lost, 0);
	EXPECT_EQ(run.infos.back().reinits, 0);
	EXPECT_GT(run.infos.back().keyframes, 3);
	for (const auto& i : run.infos)
	{
		if (!i.pose)
		{
			EXPECT_FALSE(i.reason.empty()) << "frame " << i.index;
		}
	}
	const auto ate = test::ateSim3(run.truth, run.estimate);
	const double length = pathLength(run.truth);
	EXPECT_LT(ate.ate_rmse_m, 0.01 * length) << "ATE " << ate.ate_rmse_m << " m over " << length << " m";
	// Relative motions are given while tracked, in the map's scale.
	int motions = 0;
	for (const auto& i : run.infos) motions += i.motion.has_value();
	EXPECT_GE(motions, run.tracked - 2);
}

TEST(Tracking, BlankStretchGivesLostThenRecovers)
{
	const auto cam = test::kittiCamera();
	const auto run = test::runStreet(cam, 60, VoOptions(), 25, 30);
	EXPECT_EQ(run.infos[25].state, VoState::Lost) << run.infos[25].reason;
	for (int k = 25; k < 30; ++k)
	{
		EXPECT_EQ(run.infos[static_cast<std::size_t>(k)].state, VoState::Lost) << k;
		EXPECT_FALSE(run.infos[static_cast<std::size_t>(k)].pose.has_value());
		EXPECT_NE(run.infos[static_cast<std::size_t>(k)].reason.find("features"), std::string::npos)
			<< k << ": " << run.infos[static_cast<std::size_t>(k)].reason;
	}
	// A new map within a few frames, tracked to the end.
	int back = -1;
	for (int k = 30; k < 60; ++k)
		if (run.infos[static_cast<std::size_t>(k)].new_map)
		{
			back = k;
			break;
		}
	ASSERT_GE(back, 0);
	EXPECT_LE(back, 36);
	for (int k = back; k < 60; ++k) EXPECT_EQ(run.infos[static_cast<std::size_t>(k)].state, VoState::Ok) << k;
	EXPECT_EQ(run.infos.back().reinits, 1);
	EXPECT_EQ(run.infos.back().map_id, 1);
	// The continued trajectory: each map's own Sim(3) fit is good; together the gap is bridged at
	// constant velocity and roughly the old scale, so the whole fit is looser.
	test::Run after;
	for (const auto& p : run.estimate)
		if (p.t >= 0.1 * back - 1e-9) after.estimate.push_back(p);
	const double length = pathLength(run.truth);
	EXPECT_LT(test::ateSim3(run.truth, after.estimate).ate_rmse_m, 0.01 * length);
	EXPECT_LT(test::ateSim3(run.truth, run.estimate).ate_rmse_m, 0.05 * length);
}

// A frame with fewer than min_local_inliers but at least min_weak_inliers is kept and made a
// keyframe, at most max_weak_frames in a row. With min_local_inliers out of reach every tracked
// frame is weak: known answers for the counts.
TEST(Tracking, WeakFramesAreKeptAsKeyframesAtMostMaxInARow)
{
	const auto cam = test::kittiCamera();
	VoOptions opt;
	opt.tracking.min_local_inliers = 100000;
	opt.tracking.min_weak_inliers = 20;
	opt.tracking.max_weak_frames = 2;
	const auto run = test::runStreet(cam, 12, opt);
	int first = -1;
	for (const auto& i : run.infos)
		if (i.pose && first < 0) first = static_cast<int>(i.index);
	ASSERT_GE(first, 0);
	ASSERT_LT(first + 3, 12);
	for (int k = first + 1; k <= first + 2; ++k)
	{
		const auto& i = run.infos[static_cast<std::size_t>(k)];
		EXPECT_EQ(i.state, VoState::Ok) << k << ": " << i.reason;
		EXPECT_NE(i.reason.find("weak"), std::string::npos) << k << ": " << i.reason;
		EXPECT_TRUE(i.keyframe) << k;
	}
	const auto& third = run.infos[static_cast<std::size_t>(first + 3)];
	EXPECT_NE(third.reason.find("LOST: local map"), std::string::npos) << third.reason;

	// Off (ORB-SLAM2's rule): the first frame after the initialisation is lost.
	opt.tracking.min_weak_inliers = 0;
	const auto strict = test::runStreet(cam, first + 2, opt);
	EXPECT_NE(strict.infos[static_cast<std::size_t>(first + 1)].reason.find("LOST: local map"), std::string::npos)
		<< strict.infos[static_cast<std::size_t>(first + 1)].reason;

	// Without a limit, every frame weak: tracked to the end, one keyframe each, on the true path.
	opt.tracking.min_weak_inliers = 20;
	opt.tracking.max_weak_frames = 1000;
	const auto kept = test::runStreet(cam, 30, opt);
	EXPECT_EQ(kept.lost, 0);
	EXPECT_EQ(kept.tracked, 30 - first);
	const auto ate = test::ateSim3(kept.truth, kept.estimate);
	EXPECT_LT(ate.ate_rmse_m, 0.01 * pathLength(kept.truth)) << "ATE " << ate.ate_rmse_m;
}
