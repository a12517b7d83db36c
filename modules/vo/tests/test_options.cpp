// Options: defaults load and save, every key is written, bad values name their key.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <vlo/core/error.h>
#include <vlo/vo/options.h>

using namespace vlo;
using namespace vlo::vo;

TEST(Options, RoundTripAndValidation)
{
	VoOptions a;
	a.orb.n_features = 1500;
	a.init.homography_ratio = 0.4;
	a.tracking.check_orientation = false;
	a.mapping.local_ba = false;
	mrpt::config::CConfigFileMemory ini;
	a.save(ini);
	std::vector<std::string> keys;
	ini.getAllKeys("vo.tracking", keys);
	EXPECT_GE(keys.size(), 20u);
	VoOptions b;
	b.load(mrpt::config::CConfigFileMemory(ini.getContent()));  // as text, as a user's file
	EXPECT_EQ(b.orb.n_features, 1500);
	EXPECT_DOUBLE_EQ(b.init.homography_ratio, 0.4);
	EXPECT_FALSE(b.tracking.check_orientation);
	EXPECT_FALSE(b.mapping.local_ba);
	EXPECT_NO_THROW(b.validate());

	b.orb.detector = "sift";
	try
	{
		b.validate();
		FAIL() << "no error";
	}
	catch (const InputError& e)
	{
		// Set in code, not read from a section: the key alone.
		EXPECT_EQ(std::string(e.what()), "detector: 'sift' is not one of anms, quadtree, opencv");
	}
	VoOptions c;
	c.init.homography_ratio = 1.5;
	EXPECT_THROW(c.validate(), InputError);
}
