// [scale] options: defaults, INI round trip, strict values.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <vlo/core/error.h>
#include <vlo/scale/options.h>

using namespace vlo;
using namespace vlo::scale;

TEST(Options, PaperDefaults)
{
	const ScaleOptions o;
	EXPECT_EQ(o.keypoint_test, KeypointTest::Fast9);
	EXPECT_EQ(o.epipolar_max_error, 0.5);
	EXPECT_EQ(o.min_abs_cos, 0.5);
	EXPECT_EQ(o.correction_threshold, 0.02);
	EXPECT_TRUE(o.cull_epipolar && o.cull_gradient && o.correction_enabled);
	EXPECT_NO_THROW(o.validate());
}

TEST(Options, RoundTripAndPerSensorKeypointTest)
{
	ScaleOptions a;
	a.keypoint_test = KeypointTest::Fast12Pretest;
	a.fast_threshold = 9;
	a.cull_gradient = false;
	a.ransac_tolerance = 0.03;
	mrpt::config::CConfigFileMemory ini;
	a.saveToConfigFile(ini, "scale");
	EXPECT_NE(ini.getContent().find("keypoint_test"), std::string::npos);
	// Re-parsed from text, as a user's file would be.
	const mrpt::config::CConfigFileMemory text(ini.getContent());
	ScaleOptions b;
	b.loadFromConfigFile(text, "scale");
	EXPECT_EQ(b.keypoint_test, KeypointTest::Fast12Pretest);
	EXPECT_EQ(b.fast_threshold, 9);
	EXPECT_FALSE(b.cull_gradient);
	EXPECT_EQ(b.ransac_tolerance, 0.03);

	mrpt::config::CConfigFileMemory vlp("[scale]\nkeypoint_test = fast12_pretest\nfast_threshold = 12\n");
	ScaleOptions c;
	c.loadFromConfigFile(vlp, "scale");
	EXPECT_EQ(c.keypoint_test, KeypointTest::Fast12Pretest);
	EXPECT_EQ(c.fast_threshold, 12);
	EXPECT_EQ(c.lk_window, ScaleOptions().lk_window);  // absent keys keep their defaults
}

TEST(Options, ImpossibleValuesNameTheKey)
{
	auto fails = [](const std::string& text, const std::string& key) {
		mrpt::config::CConfigFileMemory ini("[scale]\n" + text + "\n");
		ScaleOptions o;
		try
		{
			o.loadFromConfigFile(ini, "scale");
		}
		catch (const InputError& e)
		{
			return std::string(e.what()).find(key) != std::string::npos;
		}
		return false;
	};
	EXPECT_TRUE(fails("keypoint_test = orb", "keypoint_test"));
	EXPECT_TRUE(fails("epipolar_max_error = 0", "epipolar_max_error"));
	EXPECT_TRUE(fails("min_abs_cos = 1.5", "min_abs_cos"));
	EXPECT_TRUE(fails("lk_window = 20", "lk_window"));
	EXPECT_TRUE(fails("border = 2", "border"));
	EXPECT_TRUE(fails("fast12_min_count = 2", "fast12_min_count"));
	EXPECT_TRUE(fails("ransac_tolerance = 0", "ransac_tolerance"));
}
