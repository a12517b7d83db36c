// The analytic Jacobians of the reprojection residuals against Ceres' automatic differentiation.
#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <gtest/gtest.h>

#include <cstring>

#include "../src/reprojection_error.h"
#include "synthetic_scene.h"

using namespace vlo;
using namespace vlo::vo;

namespace
{
struct AutoReprojection
{
	Vec2 obs;
	double w;
	PinholeCamera c;
	template <typename T>
	bool operator()(const T* pose, const T* point, T* r) const
	{
		T p[3];
		ceres::AngleAxisRotatePoint(pose, point, p);
		for (int i = 0; i < 3; ++i) p[i] += pose[3 + i];
		r[0] = (T(c.fx) * p[0] / p[2] + T(c.cx) - T(obs.x())) * T(w);
		r[1] = (T(c.fy) * p[1] / p[2] + T(c.cy) - T(obs.y())) * T(w);
		return true;
	}
};
}  // namespace

TEST(Reprojection, AnalyticJacobiansMatchAutodiff)
{
	const auto cam = test::kittiCamera();
	const Vec2 obs(400.5, 200.25);
	const double w = 1 / 1.44;
	detail::ReprojectionError analytic(obs, w, cam);
	ceres::AutoDiffCostFunction<AutoReprojection, 2, 6, 3> autodiff(new AutoReprojection{obs, w, cam});
	for (const double angle : {0.0, 1e-9, 0.3, 2.5})
	{
		double pose[6] = {angle * 0.6, -angle * 0.8, angle * 0.1, 0.3, -0.2, 1.5};
		double X[3] = {2.0, -1.0, 12.0};
		const double* params[2] = {pose, X};
		double ra[2], rb[2], ja0[12], ja1[6], jb0[12], jb1[6];
		double* ja[2] = {ja0, ja1};
		double* jb[2] = {jb0, jb1};
		ASSERT_TRUE(analytic.Evaluate(params, ra, ja));
		ASSERT_TRUE(autodiff.Evaluate(params, rb, jb));
		for (int i = 0; i < 2; ++i) EXPECT_NEAR(ra[i], rb[i], 1e-9);
		for (int i = 0; i < 12; ++i) EXPECT_NEAR(ja0[i], jb0[i], 1e-6 * (1 + std::abs(jb0[i]))) << "angle " << angle << " d/dpose " << i;
		for (int i = 0; i < 6; ++i) EXPECT_NEAR(ja1[i], jb1[i], 1e-6 * (1 + std::abs(jb1[i]))) << "d/dX " << i;
	}
}

// The rotations shared between the observations of a pose give the very same numbers as computing
// them per observation, also when the parameters change between evaluations (a new trial step).
TEST(Reprojection, SharedRotationsGiveIdenticalNumbers)
{
	const auto cam = test::kittiCamera();
	const Vec2 obs(610.25, 180.5);
	detail::PoseRotations rotations(2);
	const detail::ReprojectionError own(obs, 0.8, cam);
	const detail::ReprojectionError shared(obs, 0.8, cam, &rotations, 1);
	double pose[6] = {0.02, -0.3, 0.01, 0.5, 0.1, -2.0};
	double X[3] = {-3.0, 1.0, 15.0};
	const double* params[2] = {pose, X};
	for (const double step : {0.0, 0.0, 1e-7, -0.25, 0.0})
	{
		pose[1] += step;
		double ra[2], rb[2], ja0[12], ja1[6], jb0[12], jb1[6];
		double* ja[2] = {ja0, ja1};
		double* jb[2] = {jb0, jb1};
		ASSERT_TRUE(own.Evaluate(params, ra, ja));
		ASSERT_TRUE(shared.Evaluate(params, rb, jb));
		EXPECT_EQ(0, std::memcmp(ra, rb, sizeof ra)) << "step " << step;
		EXPECT_EQ(0, std::memcmp(ja0, jb0, sizeof ja0)) << "step " << step;
		EXPECT_EQ(0, std::memcmp(ja1, jb1, sizeof ja1)) << "step " << step;
	}
}
