#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <vlo/core/option_table.h>
#include <vlo_test/demo_options.h>

using namespace vlo;

namespace
{
/// The message of loading `ini`'s section [s] into DemoOptions.
std::string loadError(const std::string& ini)
{
	return test::errorOf([&] { test::DemoOptions().loadFromConfigFile(mrpt::config::CConfigFileMemory(ini), "s"); });
}
}  // namespace

TEST(Range, ParsesWhatTheDocsShow)
{
	EXPECT_EQ(Range::parse("> 0").text(), "must be > 0");
	EXPECT_EQ(Range::parse(">= 1.5").text(), "must be >= 1.5");
	EXPECT_EQ(Range::parse("(0, 1]").text(), "must be in (0, 1]");
	EXPECT_EQ(Range::parse("[19, 100)").text(), "must be in [19, 100)");
	EXPECT_TRUE(Range::parse("(0, 1]").contains(1));
	EXPECT_FALSE(Range::parse("(0, 1]").contains(0));
	EXPECT_TRUE(Range::parse("[19, 100)").contains(19));
	EXPECT_FALSE(Range::parse("[19, 100)").contains(100));
	EXPECT_FALSE(Range::parse("> 0").contains(0));
	EXPECT_TRUE(Range::parse(">= 0").contains(0));
	EXPECT_TRUE(Range::parse("any").contains(-1e300));
	EXPECT_EQ(Range::parse("any").text(), "");
	for (const char* bad : {"", "0", "> x", "(0 1]", "(0, 1", "{0, 1}", ">= 1 m"}) EXPECT_THROW(Range::parse(bad), std::logic_error) << bad;
}

TEST(OptionTable, SavesAsMrptsMacrosDo)
{
	// The effective run.ini keeps MRPT's layout: same padding, same value text, the help as comment.
	test::DemoOptions d;
	mrpt::config::CConfigFileMemory ours, mrpts;
	d.saveToConfigFile(ours, "s");
	{
		auto& c = mrpts;
		const std::string s = "s";
		const double gain = 0.25;
		const int count = 3;
		const bool on = true;
		const std::string mode = "fast";
		MRPT_SAVE_CONFIG_VAR_COMMENT(gain, "a gain");
		MRPT_SAVE_CONFIG_VAR_COMMENT(count, "how many");
		MRPT_SAVE_CONFIG_VAR_COMMENT(on, "switch");
		MRPT_SAVE_CONFIG_VAR_COMMENT(mode, "speed");
		c.write(s, "table", std::string("[1.5 -2]"), mrpt::config::MRPT_SAVE_NAME_PADDING(),
			mrpt::config::MRPT_SAVE_VALUE_PADDING(), "angles [deg]");
	}
	EXPECT_EQ(ours.getContent(), mrpts.getContent());
	// ... and reads back what it wrote.
	test::DemoOptions e;
	e.gain = 0.5, e.count = 9, e.on = false, e.mode = "slow", e.table.clear();
	e.loadFromConfigFile(mrpt::config::CConfigFileMemory(ours.getContent()), "s");  // as run.ini is read
	EXPECT_DOUBLE_EQ(e.gain, 0.25);
	EXPECT_EQ(e.count, 3);
	EXPECT_TRUE(e.on);
	EXPECT_EQ(e.mode, "fast");
	EXPECT_EQ(e.table, (std::vector<double>{1.5, -2}));
}

TEST(OptionTable, RefusesWrongTypesAndRangesNamingSectionAndKey)
{
	EXPECT_EQ(loadError("[s]\ngain = 0.5\ncount = 7\non = no\nmode = slow\ntable = [10 20 30]\n"), "");
	for (const auto& [line, problem] : test::kRefusedDemoLines)
		EXPECT_EQ(loadError("[s]\n" + line + "\n"), "[s] " + test::keyOf(line) + ": " + problem);
}

TEST(OptionTable, ValidatesValuesSetInCodeAndListsItsRows)
{
	test::DemoOptions d;
	EXPECT_NO_THROW(d.validate());
	d.count = 0;
	EXPECT_THROW(d.validate(), OptionError);
	const auto rows = test::DemoOptions().rows();
	ASSERT_EQ(rows.size(), 5u);
	EXPECT_EQ(rows[0].key, "gain");
	EXPECT_EQ(rows[0].allowed, "(0, 1]");
	EXPECT_EQ(rows[3].allowed, "fast | slow");
	EXPECT_EQ(rows[3].default_text, "fast");
	EXPECT_EQ(rows[4].default_text, "[1.5 -2]");
}

TEST(DidYouMean, SuggestsTheNearestNameOnlyForATypo)
{
	const std::vector<std::string> keys{"map_radius", "voxel_size", "knn"};
	EXPECT_EQ(didYouMean("map_raduis", keys), " (did you mean map_radius?)");
	EXPECT_EQ(didYouMean("mapradius", keys), " (did you mean map_radius?)");
	EXPECT_EQ(didYouMean("kn", keys), " (did you mean knn?)");
	EXPECT_EQ(didYouMean("completely_different", keys), "");
	EXPECT_EQ(didYouMean("x", {}), "");
	// Issue 34, defect 4: "--set pipeline.threads=7" was answered "did you mean 1?".
	EXPECT_EQ(didYouMean("7", {"1", "2", "auto"}), "");
	EXPECT_EQ(didYouMean("vlp", {"lo", "vo", "vlo"}), " (did you mean vlo?)");
}
