// The end-of-run table of times per stage: known values in, mean, p95 (nearest rank), max and count out.
#include <gtest/gtest.h>
#include <vlo/pipeline/stage_timings.h>

#include <algorithm>

using namespace vlo;
using namespace vlo::pipeline;

TEST(StageTimings, MeanP95MaxAndCountOfEachTimingColumn)
{
	kernel::FrameTable t;
	for (int i = 1; i <= 20; ++i)
	{
		t.newRow();
		t.set("frame", static_cast<long long>(i));
		t.set("lo_status", std::string("ok"));
		t.set("ms_lo_mapping", double(21 - i), 2);  // 20 .. 1, in no sorted order of rows
		if (i % 2 == 0) t.set("ms_scale", 4.0, 2);  // runs every other frame only
		t.set("ms_total", 100.0 + i, 2);
	}
	const auto s = stageTimings(t);
	ASSERT_EQ(s.size(), 3u);
	EXPECT_EQ(s[0].stage, "ms_lo_mapping");
	EXPECT_EQ(s[0].count, 20u);
	EXPECT_DOUBLE_EQ(s[0].mean, 10.5);
	EXPECT_DOUBLE_EQ(s[0].p95, 19.0);  // the 19th of 20 sorted values
	EXPECT_DOUBLE_EQ(s[0].max, 20.0);
	EXPECT_EQ(s[1].stage, "ms_scale");
	EXPECT_EQ(s[1].count, 10u);
	EXPECT_DOUBLE_EQ(s[1].p95, 4.0);
	EXPECT_EQ(s[2].stage, "ms_total");
	EXPECT_DOUBLE_EQ(s[2].max, 120.0);

	const std::string text = formatStageTimings(s);
	EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
	EXPECT_NE(text.find("ms_lo_mapping     10.50     19.00     20.00     20"), std::string::npos) << text;
}

TEST(StageTimings, NoTimingColumnsNoRows)
{
	kernel::FrameTable t;
	t.set("frame", 0LL);
	EXPECT_TRUE(stageTimings(t).empty());
}
