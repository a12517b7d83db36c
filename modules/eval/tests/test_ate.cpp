#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/eval/ate.h>

#include "eval_test_utils.h"

using namespace vlo;
using namespace vlo::eval;
using namespace vlo::test;

namespace
{
/// Every pose moved by a fixed similarity S (S applied on the left, as a change of world frame).
Trajectory transformed(Trajectory tr, const Sim3& S)
{
	for (auto& p : tr)
	{
		p.pose.translation() = S * Eigen::Vector3d(p.pose.translation());
		p.pose.linear() = S.R * p.pose.linear();
	}
	return tr;
}

Sim3 offset(double s)
{
	Sim3 S;
	S.s = s;
	S.R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
	S.t = Eigen::Vector3d(5, -3, 1);
	return S;
}
}  // namespace

TEST(Ate, IdenticalTrajectoriesHaveZeroErrorWithEveryAlignment)
{
	const Trajectory gt = wiggly(200);
	for (const Alignment al : {Alignment::None, Alignment::SE3, Alignment::Sim3})
	{
		const AteResult r = computeAte(gt, gt, al);
		EXPECT_NEAR(r.ate_rmse_m, 0, 1e-9) << toString(al);
		ASSERT_TRUE(r.are_rmse_deg.has_value());
		EXPECT_NEAR(*r.are_rmse_deg, 0, 1e-6) << toString(al);
		EXPECT_NEAR(*r.sim3_scale, 1, 1e-12);
	}
}

TEST(Ate, RigidOffsetVanishesUnderSe3Alignment)
{
	const Trajectory gt = wiggly(200), est = transformed(gt, offset(1.0).inverse());
	const AteResult se3 = computeAte(gt, est, Alignment::SE3);
	EXPECT_NEAR(se3.ate_rmse_m, 0, 1e-9);
	EXPECT_NEAR(*se3.are_rmse_deg, 0, 1e-6);
	const AteResult none = computeAte(gt, est, Alignment::None);
	EXPECT_GT(none.ate_rmse_m, 1.0);
	// Unaligned, every orientation is off by the offset's 0.4 rad.
	EXPECT_NEAR(*none.are_rmse_deg, 0.4 * 180 / M_PI, 1e-9);
}

TEST(Ate, ScaledEstimateNeedsSim3)
{
	// An unscaled monocular estimate: the ground truth seen at half size in another frame.
	const Trajectory gt = wiggly(200), est = transformed(gt, offset(0.5));
	const AteResult sim3 = computeAte(gt, est, Alignment::Sim3);
	EXPECT_NEAR(sim3.ate_rmse_m, 0, 1e-9);
	EXPECT_NEAR(*sim3.are_rmse_deg, 0, 1e-6);
	EXPECT_NEAR(*sim3.sim3_scale, 2.0, 1e-12);
	EXPECT_NEAR(sim3.alignment.s, 2.0, 1e-12);
	const AteResult se3 = computeAte(gt, est, Alignment::SE3);
	EXPECT_GT(se3.ate_rmse_m, 1.0);  // half-size circle of radius 10: metres off
	EXPECT_NEAR(*se3.are_rmse_deg, 0, 1e-6);  // scale does not touch orientations
	EXPECT_NEAR(*se3.sim3_scale, 2.0, 1e-12);  // reported whatever the alignment
	EXPECT_GT(computeAte(gt, est, Alignment::None).ate_rmse_m, se3.ate_rmse_m);
}

TEST(Ate, KnownConstantPositionErrorGivesThatRmse)
{
	// Unaligned, a constant 0.3 m offset along z is an ATE of exactly 0.3 m.
	const Trajectory gt = wiggly(100);
	Trajectory est = gt;
	for (auto& p : est) p.pose.translation().z() += 0.3;
	const AteResult r = computeAte(gt, est, Alignment::None);
	EXPECT_NEAR(r.ate_rmse_m, 0.3, 1e-12);
	EXPECT_NEAR(r.ate_max_m, 0.3, 1e-12);
	EXPECT_NEAR(computeAte(gt, est, Alignment::SE3).ate_rmse_m, 0, 1e-9);
}

TEST(Ate, ErrorPerAxisIsInTheTruthsOwnFrameAtEachPose)
{
	// Unaligned, an error of (0.1 ahead, 0.2 left, 0.3 up) in each pose's own frame, whichever way the truth
	// faces (wiggly turns, rolls and pitches), is exactly that per axis.
	const Trajectory gt = wiggly(100);
	Trajectory est = gt;
	const Eigen::Vector3d body(0.1, -0.2, 0.3);
	for (auto& p : est) p.pose.translation() += p.pose.linear() * body;
	const AteResult r = computeAte(gt, est, Alignment::None);
	ASSERT_TRUE(r.ate_rmse_axes_m.has_value());
	EXPECT_NEAR(r.ate_rmse_axes_m->x(), 0.1, 1e-12);
	EXPECT_NEAR(r.ate_rmse_axes_m->y(), 0.2, 1e-12);
	EXPECT_NEAR(r.ate_rmse_axes_m->z(), 0.3, 1e-12);
	EXPECT_NEAR(r.ate_rmse_m, body.norm(), 1e-12);
	EXPECT_FALSE(computeAte(gt, est, Alignment::None, false).ate_rmse_axes_m.has_value());
}

TEST(Ate, TranslationOnlyGroundTruthHasNoAre)
{
	const Trajectory est = wiggly(100);
	Trajectory gt = est;
	for (auto& p : gt) p.pose.linear().setIdentity();  // RTK: positions only
	const AteResult r = computeAte(gt, est, Alignment::SE3, false);
	EXPECT_NEAR(r.ate_rmse_m, 0, 1e-9);
	EXPECT_FALSE(r.are_rmse_deg.has_value());
}

TEST(Ate, TooFewPosesAndMotionlessEstimate)
{
	const Trajectory gt = wiggly(2);
	EXPECT_THROW(computeAte(gt, gt, Alignment::SE3), InputError);
	const Trajectory moving = wiggly(10);
	Trajectory still = moving;
	for (auto& p : still) p.pose = Eigen::Isometry3d::Identity();
	EXPECT_THROW(computeAte(moving, still, Alignment::Sim3), InputError);
	const AteResult r = computeAte(moving, still, Alignment::SE3);  // fine, but it has no scale
	EXPECT_FALSE(r.sim3_scale.has_value());
}

TEST(Ate, ParsesAlignmentNames)
{
	EXPECT_EQ(parseAlignment("sim3"), Alignment::Sim3);
	EXPECT_EQ(parseAlignment("se3"), Alignment::SE3);
	EXPECT_EQ(parseAlignment("none"), Alignment::None);
	EXPECT_THROW(parseAlignment("SE3"), InputError);
}

namespace
{
/// Positions moved by a few centimetres in a fixed pseudo-random pattern, orientations kept.
Trajectory jittered(Trajectory tr, double amplitude_m)
{
	for (std::size_t i = 0; i < tr.size(); ++i)
		tr[i].pose.translation() += amplitude_m *
			Eigen::Vector3d(std::sin(12.9898 * i), std::sin(78.233 * i + 1), std::sin(37.719 * i + 2));
	return tr;
}
}  // namespace

// Issue 34, defect 1: on a straight drive the positions cannot fix the alignment's rotation about the
// direction of travel, and Umeyama picks it from the position noise: ARE of tens of degrees for an estimate
// whose orientations are exact.
TEST(Ate, StraightPathTakesTheRollAboutItsDirectionFromTheOrientations)
{
	const Trajectory gt = fromSteps(50, arcStep(1.0, 0));  // 49 m straight ahead
	const Trajectory est = transformed(jittered(gt, 0.05), offset(1));
	for (Alignment align : {Alignment::SE3, Alignment::Sim3})
	{
		const AteResult r = computeAte(gt, est, align);
		ASSERT_TRUE(r.are_rmse_deg.has_value());
		EXPECT_LT(*r.are_rmse_deg, 0.2) << toString(align);  // the orientations are exact
		ASSERT_TRUE(r.are_roll_from_orientations_deg.has_value());
		EXPECT_GT(r.are_roll_uncertainty_deg, 1.0);
		EXPECT_LT(r.ate_rmse_m, 0.1);  // the positions' fit is kept for ATE
	}
	const AteResult none = computeAte(gt, jittered(gt, 0.05), Alignment::None);
	EXPECT_NEAR(*none.are_rmse_deg, 0, 1e-9);
	EXPECT_FALSE(none.are_roll_from_orientations_deg.has_value());
}

TEST(Ate, CurvedPathKeepsThePositionsRotationForAre)
{
	// 20 m of a 10 m radius turn climbing and falling 1 m: the positions fix every rotation.
	const Trajectory gt = wiggly(200);
	Trajectory est = transformed(jittered(gt, 0.01), offset(1));
	for (auto& p : est) p.pose.linear() = p.pose.linear() * Rz(0.01);  // 0.573 deg off everywhere
	const AteResult r = computeAte(gt, est, Alignment::SE3);
	EXPECT_FALSE(r.are_roll_from_orientations_deg.has_value());
	EXPECT_NEAR(*r.are_rmse_deg, 0.573, 0.1);
}
