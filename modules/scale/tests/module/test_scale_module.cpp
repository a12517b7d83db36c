// The "lidar_depth" module as the metric VO sees it: created by name, configured from an INI, given
// a rendered frame pair and a VO motion 0.5 times too short, it decides to scale the whole map by 2
// (the first scale of a map) and reports that decision in frames.csv.
#include <gtest/gtest.h>
#include <vlo/kernel/scale_correction.h>

#include "../synthetic_scene.h"

#include <cmath>

using namespace vlo;
using namespace vlo::scale::test;

namespace
{
struct Fixture
{
	Frame prev, cur;
	kernel::VisualOdometryStep vo;  ///< the camera motion of a VO whose map unit is 0.5 m
	std::unique_ptr<kernel::ScaleCorrectionModule> module;
	kernel::FrameTable table;

	Fixture()
	{
		static const FramePair p = makePair(streetScene(3), hdl64());
		prev.has_image = prev.has_scan = cur.has_image = true;
		prev.image = mrpt::img::CImage(p.prev, mrpt::img::SHALLOW_COPY);
		cur.image = mrpt::img::CImage(p.cur, mrpt::img::SHALLOW_COPY);
		cur.index = 1;
		prev.scan = p.scan;
		prev.rig = cur.rig = p.rig;
		vo.camera_motion = withScaledTranslation(p.cur_T_prev, 0.5).inverse();
		vo.new_map = true;
		auto config = kernel::RunConfig::fromString("[scale]\nkeypoint_test = fast9\n", "test.ini");
		module = kernel::registry<kernel::ScaleCorrectionModule>().create("lidar_depth", "test");
		module->configure(config, 0);
		config.checkAllKeysUsed();
	}

	kernel::ScaleCorrection step(const Frame* previous)
	{
		table.newRow();
		return module->process(previous, cur, vo, table);
	}
	std::string last(const std::string& column) const { return table.cell(table.rows() - 1, column); }
};
}  // namespace

TEST(ScaleModule, TheFirstEstimateDecidesToScaleTheWholeMap)
{
	Fixture f;
	const kernel::ScaleCorrection a = f.step(&f.prev);
	EXPECT_EQ(a.kind, kernel::ScaleCorrection::Kind::Initial);
	EXPECT_NEAR(a.factor, 2.0, 0.02);
	EXPECT_EQ(a.why, "initial");
	EXPECT_EQ(f.last("scale_decision"), "initial");
	EXPECT_NEAR(std::stod(f.last("scale_applied")), 2.0, 0.02);
	// The estimate's relative standard error, for the motion's quality: spread / s / sqrt(inliers).
	const auto number = [&f](const std::string& column) { return f.table.numbers(column).back(); };
	ASSERT_GE(number("scale_inliers"), 2);
	EXPECT_DOUBLE_EQ(a.relative_error, number("scale_spread") / number("scale_s") / std::sqrt(number("scale_inliers")));
	EXPECT_GT(a.relative_error, 0);
	EXPECT_LT(a.relative_error, 0.01);
	ASSERT_EQ(f.module->figures().size(), 3u);
	EXPECT_EQ(f.module->figures()[2], std::make_pair(std::string("scale_corrections"), 0.0));  // initial only
}

TEST(ScaleModule, ANewMapIsScaledWholeAgain)
{
	Fixture f;
	ASSERT_EQ(f.step(&f.prev).kind, kernel::ScaleCorrection::Kind::Initial);
	f.vo.new_map = false;
	const kernel::ScaleCorrection same = f.step(&f.prev);  // the map is metric: 2 now means a drift
	EXPECT_NE(same.kind, kernel::ScaleCorrection::Kind::Initial);
	f.vo.new_map = true;
	const kernel::ScaleCorrection again = f.step(&f.prev);
	EXPECT_EQ(again.kind, kernel::ScaleCorrection::Kind::Initial);  // a fresh map, initial again
	EXPECT_NEAR(again.factor, 2.0, 0.02);
}

TEST(ScaleModule, NothingWithoutAPreviousFrameOrAMotion)
{
	Fixture f;
	EXPECT_FALSE(f.step(nullptr).apply());
	EXPECT_EQ(f.last("scale_decision"), "no previous scan");
	f.vo.camera_motion.reset();
	const kernel::ScaleCorrection none = f.step(&f.prev);
	EXPECT_FALSE(none.apply());
	EXPECT_EQ(none.why, "no VO motion");
	EXPECT_TRUE(std::isnan(none.relative_error));  // no estimate
	EXPECT_EQ(f.last("scale_decision"), "no VO motion");
}
