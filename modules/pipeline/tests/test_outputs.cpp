#include <gtest/gtest.h>
#include <vlo/pipeline/frame_table.h>
#include <vlo/pipeline/global_map.h>

#include <cmath>
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

TEST(GlobalMap, OnePointPerVoxelInWorldFrame)
{
	GlobalMap map(0.5, 50.0);
	PointCloud scan{{0.1f, 0.1f, 0.1f, 1}, {0.2f, 0.2f, 0.2f, 2}, {1.1f, 0.1f, 0.1f, 3}, {80.f, 0, 0, 4}};
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
	pose.translation() = Eigen::Vector3d(10, 0, 0);
	map.insert(scan, pose);
	ASSERT_EQ(map.points().size(), 2u);  // two share a voxel, one is beyond max_range
	EXPECT_NEAR(map.points()[0].x, 10.1f, 1e-5);
	EXPECT_NEAR(map.points()[1].x, 11.1f, 1e-5);
	map.insert(scan, pose);  // the same place again adds nothing
	EXPECT_EQ(map.points().size(), 2u);
}
