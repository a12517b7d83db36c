#include <gtest/gtest.h>
#include <vlo/kernel/frame_table.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

using namespace vlo;
using namespace vlo::kernel;

TEST(FrameTable, ColumnsInFirstSeenOrderAndCsvQuoting)
{
	FrameTable t;
	t.newRow();
	t.set("frame", 0LL);
	t.set("reason", std::string("too few, \"sharp\" points"));
	t.newRow();
	t.set("frame", 1LL);
	t.set("scale", 1.02345, 3);
	ASSERT_EQ(t.columns().size(), 3u);
	EXPECT_EQ(t.columns()[2], "scale");
	EXPECT_EQ(t.cell(0, "scale"), "");
	EXPECT_EQ(t.cell(1, "scale"), "1.023");
	const auto s = t.numbers("scale");
	EXPECT_TRUE(std::isnan(s[0]));
	EXPECT_DOUBLE_EQ(s[1], 1.02345);  // the number as set: only the CSV rounds it

	t.write("frame_table_test.csv");
	std::ifstream in("frame_table_test.csv");
	std::stringstream ss;
	ss << in.rdbuf();
	EXPECT_EQ(ss.str(), "frame,reason,scale\n0,\"too few, \"\"sharp\"\" points\",\n1,,1.023\n");
	std::remove("frame_table_test.csv");
}

TEST(FrameTable, DocumentedColumnOrderWhateverTheOrderOfWriting)
{
	FrameTable t;
	t.set("frame", 0LL);
	t.set("t", 0.0, 6);
	t.set("vo_state", std::string("OK"));
	t.set("ms_vo_track", 1.0, 2);
	t.set("lo_status", std::string("ok"));
	t.set("ms_lo_mapping", 2.0, 2);
	t.set("x", 1.0, 3);
	t.set("y", 2.0, 3);
	t.set("z", 3.0, 3);
	t.set("ms_total", 4.0, 2);
	t.newRow();
	t.set("scale_s", 1.0, 3);  // a module that starts writing at a later frame
	t.set("ms_scale", 1.0, 2);
	t.set("vo_metric_motion", true);
	const std::vector<std::string> expected{"frame", "t", "x", "y", "z", "vo_state", "vo_metric_motion", "lo_status",
		"scale_s", "ms_vo_track", "ms_lo_mapping", "ms_scale", "ms_total"};
	EXPECT_EQ(t.columns(), expected);
}

// An estimator's StageTimes become one column per stage, in its declared order, whatever ran first.
TEST(FrameTable, SetTimesWritesOneColumnPerStage)
{
	StageTimes ms({"features", "odometry", "mapping"});
	ms.add("mapping", 1.234);
	ms.add("features", 2.0);
	FrameTable t;
	t.setTimes("lo_", ms);
	EXPECT_EQ(t.columns(), (std::vector<std::string>{"ms_lo_features", "ms_lo_odometry", "ms_lo_mapping"}));
	EXPECT_EQ(t.cell(0, "ms_lo_mapping"), "1.23");
	EXPECT_EQ(t.cell(0, "ms_lo_odometry"), "0.00");
}

TEST(FrameTable, NoNegativeZero)
{
	FrameTable t;
	t.set("a", -0.0001, 3);
	t.set("b", -0.0, 2);
	t.set("c", -0.0006, 3);
	t.set("d", -1e-9, 0);
	EXPECT_EQ(t.cell(0, "a"), "0.000");
	EXPECT_EQ(t.cell(0, "b"), "0.00");
	EXPECT_EQ(t.cell(0, "c"), "-0.001");
	EXPECT_EQ(t.cell(0, "d"), "0");
}

TEST(FrameTable, SetCellsMergesOneTablePerStageInTheStagesOrder)
{
	FrameTable merged;
	for (long long i = 0; i < 2; ++i)
	{
		FrameTable motion, lidar;  // what each stage wrote for frame i on its own thread
		if (i == 1) motion.set("vo_late", 7LL);  // a column first seen at the second frame
		motion.set("vo_state", std::string("first"));
		motion.set("vo_state", std::string(i == 0 ? "INIT" : "OK"));  // the last value counts
		lidar.set("lo_iterations", 3 + i);
		merged.newRow();
		merged.set("frame", i);
		merged.setCells(motion);
		merged.setCells(lidar);
		merged.setCells(FrameTable());  // an empty part adds nothing
	}
	ASSERT_EQ(merged.rows(), 2u);
	EXPECT_EQ(merged.columns(), (std::vector<std::string>{"frame", "vo_state", "vo_late", "lo_iterations"}));
	EXPECT_EQ(merged.cell(0, "vo_state"), "INIT");
	EXPECT_EQ(merged.cell(1, "vo_state"), "OK");
	EXPECT_EQ(merged.cell(0, "vo_late"), "");
	EXPECT_EQ(merged.cell(1, "vo_late"), "7");
	EXPECT_EQ(merged.cell(1, "lo_iterations"), "4");
}

TEST(FrameTable, SetCellsAtFillsAnEarlierRowOnly)
{
	FrameTable t;
	for (long long i = 0; i < 3; ++i)
	{
		t.newRow();
		t.set("frame", i);
		t.set("lo_points", 100 + i);
	}
	FrameTable loop;  // a stage whose result for frame 1 came after frame 2's row
	loop.set("loop_candidate", 0LL);
	loop.set("loop_accepted", true);
	t.setCellsAt(1, loop);
	EXPECT_EQ(t.cell(1, "loop_candidate"), "0");
	EXPECT_EQ(t.cell(1, "loop_accepted"), "1");
	EXPECT_EQ(t.cell(0, "loop_candidate"), "");
	EXPECT_EQ(t.cell(2, "loop_accepted"), "");
	EXPECT_EQ(t.cell(2, "lo_points"), "102");  // the rows' own cells untouched
	EXPECT_THROW(t.setCellsAt(3, loop), std::out_of_range);
	t.set("lo_points", 7LL);  // set() still writes the last row
	EXPECT_EQ(t.cell(2, "lo_points"), "7");
}
