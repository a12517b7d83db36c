#include <gtest/gtest.h>
#include <vlo/kernel/frame_table.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

using namespace vlo;

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
	EXPECT_DOUBLE_EQ(s[1], 1.023);

	t.write("frame_table_test.csv");
	std::ifstream in("frame_table_test.csv");
	std::stringstream ss;
	ss << in.rdbuf();
	EXPECT_EQ(ss.str(), "frame,reason,scale\n0,\"too few, \"\"sharp\"\" points\",\n1,,1.023\n");
	std::remove("frame_table_test.csv");
}
