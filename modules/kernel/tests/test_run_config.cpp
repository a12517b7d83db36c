#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileBase.h>
#include <vlo/core/error.h>
#include <vlo/kernel/run_config.h>

using namespace vlo;

namespace
{
struct DemoOptions : public mrpt::config::CLoadableOptions
{
	int count = 5;
	double gain = 0.5;
	bool enabled = true;
	std::string mode = "fast";

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override
	{
		MRPT_LOAD_CONFIG_VAR(count, int, c, s);
		MRPT_LOAD_CONFIG_VAR(gain, double, c, s);
		MRPT_LOAD_CONFIG_VAR(enabled, bool, c, s);
		MRPT_LOAD_CONFIG_VAR(mode, string, c, s);
	}
	void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override
	{
		MRPT_SAVE_CONFIG_VAR_COMMENT(count, "how many");
		MRPT_SAVE_CONFIG_VAR_COMMENT(gain, "");
		MRPT_SAVE_CONFIG_VAR_COMMENT(enabled, "");
		MRPT_SAVE_CONFIG_VAR_COMMENT(mode, "");
	}
};

std::string errorOf(const std::function<void()>& f)
{
	try
	{
		f();
	}
	catch (const InputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(RunConfig, LoadsValuesAndOverridesAndWritesEffectiveIni)
{
	auto cfg = RunConfig::fromString("@define G 2.5\n[demo]\ncount = 7\ngain = ${G}\n", "a.ini", {"demo.mode=slow"});
	DemoOptions o;
	cfg.load(o, "demo");
	EXPECT_EQ(o.count, 7);
	EXPECT_DOUBLE_EQ(o.gain, 2.5);
	EXPECT_EQ(o.mode, "slow");
	EXPECT_NO_THROW(cfg.checkAllKeysUsed());
	const std::string eff = cfg.effectiveIni();
	EXPECT_NE(eff.find("count"), std::string::npos);
	EXPECT_NE(eff.find("enabled"), std::string::npos);  // defaults are written too
}

TEST(RunConfig, DottedSectionOverride)
{
	auto cfg = RunConfig::fromString("", "a.ini", {"loam.odometry.count=3"});
	DemoOptions o;
	cfg.load(o, "loam.odometry");
	EXPECT_EQ(o.count, 3);
}

TEST(RunConfig, RejectsUnknownSectionKeyAndBadValues)
{
	{
		auto cfg = RunConfig::fromString("[demo]\ncountt = 7\n", "a.ini");
		DemoOptions o;
		cfg.load(o, "demo");
		EXPECT_NE(errorOf([&] { cfg.checkAllKeysUsed(); }).find("unknown key 'countt' in section [demo]"), std::string::npos);
	}
	{
		auto cfg = RunConfig::fromString("[demoo]\ncount = 7\n", "a.ini");
		DemoOptions o;
		cfg.load(o, "demo");
		EXPECT_NE(errorOf([&] { cfg.checkAllKeysUsed(); }).find("unknown section [demoo]"), std::string::npos);
	}
	for (const char* bad : {"count = 2.5x", "gain = abc", "enabled = maybe"})
	{
		auto cfg = RunConfig::fromString(std::string("[demo]\n") + bad + "\n", "a.ini");
		DemoOptions o;
		const std::string err = errorOf([&] { cfg.load(o, "demo"); });
		EXPECT_NE(err.find("a.ini: [demo]"), std::string::npos) << bad;
	}
	EXPECT_FALSE(errorOf([] { RunConfig::fromString("", "a.ini", {"nodot=1"}); }).empty());
}
