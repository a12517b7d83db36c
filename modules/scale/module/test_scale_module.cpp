// The "lidar_depth" module as the metric VO sees it: created by name, configured from an INI, given
// a rendered frame pair and a VO motion 0.5 times too short, it asks the caller to scale the whole
// map by 2 (the first scale of a map) and reports what it applied in frames.csv.
#include <gtest/gtest.h>
#include <vlo/kernel/scale_correction.h>

#include "../tests/synthetic_scene.h"

using namespace vlo;
using namespace vlo::scale::test;

namespace
{
struct Fixture
{
	Frame prev, cur;
	MonocularState vo;  ///< the camera motion of a VO whose map unit is 0.5 m
	std::unique_ptr<ScaleCorrectionModule> module;
	FrameTable table;
	std::vector<std::pair<double, bool>> rescales;

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
		auto config = RunConfig::fromString("[scale]\nkeypoint_test = fast9\n", "test.ini");
		module = registry<ScaleCorrectionModule>().create("lidar_depth", "test");
		module->configure(config, 0);
		config.checkAllKeysUsed();
	}

	ScaleApplied step(const Frame* previous, bool vo_has_map)
	{
		table.newRow();
		return module->process(previous, cur, vo, [&](double f, bool whole) {
			rescales.push_back({f, whole});
			return vo_has_map;
		}, table);
	}
	std::string last(const std::string& column) const { return table.cell(table.rows() - 1, column); }
};
}  // namespace

TEST(ScaleModule, TheFirstEstimateScalesTheWholeMapThroughTheCaller)
{
	Fixture f;
	const ScaleApplied a = f.step(&f.prev, true);
	ASSERT_EQ(f.rescales.size(), 1u);
	EXPECT_NEAR(f.rescales[0].first, 2.0, 0.02);
	EXPECT_TRUE(f.rescales[0].second);
	EXPECT_TRUE(a.initial);
	EXPECT_EQ(a.factor, f.rescales[0].first);
	EXPECT_EQ(f.last("scale_decision"), "initial");
	EXPECT_NEAR(std::stod(f.last("scale_applied")), 2.0, 0.02);
	ASSERT_EQ(f.module->figures().size(), 3u);
	EXPECT_EQ(f.module->figures()[2], std::make_pair(std::string("scale_corrections"), 0.0));  // initial only
}

TEST(ScaleModule, AVoWithoutMapIsAskedAgainAtTheNextEstimate)
{
	Fixture f;
	const ScaleApplied a = f.step(&f.prev, false);
	EXPECT_EQ(a.factor, 1.0);
	EXPECT_EQ(f.last("scale_decision"), "not applied (no VO map)");
	f.vo.new_map = false;
	const ScaleApplied b = f.step(&f.prev, true);
	ASSERT_EQ(f.rescales.size(), 2u);
	EXPECT_TRUE(f.rescales[1].second);  // initial again, not a correction
	EXPECT_TRUE(b.initial);
}

TEST(ScaleModule, NothingWithoutAPreviousFrameOrAMotion)
{
	Fixture f;
	f.step(nullptr, true);
	EXPECT_EQ(f.last("scale_decision"), "no previous scan");
	f.vo.camera_motion.reset();
	f.step(&f.prev, true);
	EXPECT_EQ(f.last("scale_decision"), "no VO motion");
	EXPECT_TRUE(f.rescales.empty());
}
