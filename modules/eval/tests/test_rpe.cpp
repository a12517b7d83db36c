// Relative pose error, closed form: a constant step error, a yaw error per step, and the ground
// truth's own constant-velocity miss.
#include <gtest/gtest.h>
#include <vlo/eval/rpe.h>

#include "eval_test_utils.h"

using namespace vlo;
using namespace vlo::eval;
using namespace vlo::test;

TEST(Rpe, StepTooLongByTenCentimetres)
{
	const Trajectory gt = fromSteps(50, makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0, 0)));
	const Trajectory est = fromSteps(50, makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.1, 0, 0)));
	const RpeResult r = computeRpe(gt, est);
	EXPECT_EQ(r.n, 49u);
	EXPECT_NEAR(r.t_rmse_m, 0.1, 1e-12);
	EXPECT_NEAR(r.t_rmse_axes_m.x(), 0.1, 1e-12);
	EXPECT_NEAR(r.t_rmse_axes_m.y(), 0.0, 1e-12);
	EXPECT_NEAR(r.r_rmse_deg, 0.0, 1e-9);
	EXPECT_NEAR(r.cv_t_rmse_m, 0.0, 1e-12);  // the ground truth drives at constant velocity
}

TEST(Rpe, YawErrorPerStepAndAlternatingSpeed)
{
	// Ground truth alternates 1.0 m and 1.2 m steps: constant velocity misses 0.2 m every step.
	Trajectory gt(41);
	for (std::size_t i = 1; i < gt.size(); ++i)
	{
		gt[i].t = 0.1 * static_cast<double>(i);
		gt[i].pose = gt[i - 1].pose * makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(i % 2 ? 1.0 : 1.2, 0, 0));
	}
	// The estimate has each step's translation right but turns 0.01 rad too much per step.
	Trajectory est = gt;
	for (std::size_t i = 1; i < est.size(); ++i)
	{
		const Eigen::Isometry3d step = gt[i - 1].pose.inverse() * gt[i].pose;
		est[i].pose = est[i - 1].pose * makePose(Rz(0.01), step.translation());
	}
	const RpeResult r = computeRpe(gt, est);
	EXPECT_NEAR(r.t_rmse_m, 0.0, 1e-9);
	EXPECT_NEAR(r.r_rmse_deg, 0.01 * 180.0 / M_PI, 1e-9);
	EXPECT_NEAR(r.cv_t_rmse_m, 0.2, 1e-12);
	EXPECT_NEAR(r.cv_r_rmse_deg, 0.0, 1e-9);
}
