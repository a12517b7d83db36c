// RobustWeight: rho in closed form at a few squared residuals, and its IRLS weight as rho'(s).
#include <gtest/gtest.h>
#include <vlo/core/robust_pose_solver.h>

#include <cmath>

using vlo::RobustWeight;

TEST(RobustWeight, RhoInClosedFormAndTheWeightIsItsDerivative)
{
	const RobustWeight none(RobustWeight::None, 2.0), huber(RobustWeight::Huber, 2.0), cauchy(RobustWeight::Cauchy, 2.0);
	EXPECT_DOUBLE_EQ(none.rho(9.0), 9.0);
	EXPECT_DOUBLE_EQ(huber.rho(3.0), 3.0);  // inside a^2 = 4: the square itself
	EXPECT_DOUBLE_EQ(huber.rho(9.0), 2 * 2.0 * 3.0 - 4.0);  // 2 a sqrt(s) - a^2
	EXPECT_DOUBLE_EQ(cauchy.rho(12.0), 4.0 * std::log(4.0));  // a^2 log(1 + s / a^2)
	for (const RobustWeight* w : {&none, &huber, &cauchy})
		for (double s : {0.5, 3.0, 9.0, 40.0})
		{
			const double h = 1e-6 * s;
			EXPECT_NEAR((*w)(s), (w->rho(s + h) - w->rho(s - h)) / (2 * h), 1e-6) << s;
		}
}
