// The adaptive threshold on a known sequence of model deviations.
#include <gtest/gtest.h>
#include <vlo/icp/adaptive_threshold.h>

#include <cmath>

#include "scene.h"

namespace vlo::icp::test
{
TEST(AdaptiveThreshold, ModelErrorBoundsThePointDisplacement)
{
	AdaptiveThreshold th(2.0, 0.1, 100.0);
	EXPECT_DOUBLE_EQ(th.modelError(motion(0.3, 0.4, 0, 0)), 0.5);
	// 0.5 deg moves a point at 100 m by the chord 2 * 100 * sin(0.25 deg).
	EXPECT_NEAR(th.modelError(motion(0, 0, 0, 0.5)), 200 * std::sin(0.25 * M_PI / 180), 1e-9);
}

TEST(AdaptiveThreshold, IsTheRmsOfTheDeviationsAboveMinMotion)
{
	AdaptiveThreshold th(2.0, 0.1, 100.0);
	EXPECT_DOUBLE_EQ(th.sigma(), 2.0);  // nothing seen yet
	th.addDeviation(motion(0.05, 0, 0, 0));  // standing still: ignored
	EXPECT_DOUBLE_EQ(th.sigma(), 2.0);
	EXPECT_EQ(th.samples(), 0u);
	th.addDeviation(motion(0.3, 0, 0, 0));
	EXPECT_DOUBLE_EQ(th.sigma(), 0.3);
	th.addDeviation(motion(0, 0.4, 0, 0));
	EXPECT_NEAR(th.sigma(), std::sqrt((0.09 + 0.16) / 2), 1e-12);
	th.addDeviation(motion(0.1, 0, 0, 0.2));  // 0.1 + 200 sin(0.1 deg) = 0.4491
	const double e = 0.1 + 200 * std::sin(0.1 * M_PI / 180);
	EXPECT_NEAR(th.sigma(), std::sqrt((0.09 + 0.16 + e * e) / 3), 1e-9);
	EXPECT_EQ(th.samples(), 3u);
}
}  // namespace vlo::icp::test
