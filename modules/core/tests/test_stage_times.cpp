#include <gtest/gtest.h>
#include <vlo/core/stage_times.h>

#include <stdexcept>

using vlo::StageTimes;

// Declared order is report order; a stage run in pieces adds up; a skipped one reports 0.
TEST(StageTimes, DeclaredOrderAccumulatesAndSums)
{
	StageTimes t({"features", "odometry", "mapping"});
	t.add("mapping", 2.5);
	t.add("features", 1.0);
	t.add("mapping", 0.5);
	ASSERT_EQ(t.stages().size(), 3u);
	EXPECT_EQ(t.stages()[0].first, "features");
	EXPECT_EQ(t.stages()[2].first, "mapping");
	EXPECT_DOUBLE_EQ(t.ms("mapping"), 3.0);
	EXPECT_DOUBLE_EQ(t.ms("odometry"), 0.0);
	EXPECT_DOUBLE_EQ(t.total(), 4.0);
}

TEST(StageTimes, UndeclaredStageIsAnError)
{
	StageTimes t({"features"});
	EXPECT_THROW(t.add("feature", 1.0), std::logic_error);
	EXPECT_THROW(t.ms("mapping"), std::logic_error);
}
