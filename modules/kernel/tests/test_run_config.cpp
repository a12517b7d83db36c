#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileBase.h>
#include <vlo/core/error.h>
#include <vlo/kernel/run_config.h>

#include <fstream>

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

TEST(RunConfig, FilesThatAreNotIniAreRefusedNamingTheFile)
{
	const std::string dir = ::testing::TempDir();
	const auto errorFor = [&](const std::string& name, const std::string& content) {
		const std::string path = dir + "/" + name;
		std::ofstream(path, std::ios::binary) << content;
		return errorOf([&] { RunConfig::fromFile(path); });
	};
	const auto expectError = [&](const std::string& name, const std::string& content, const std::string& text) {
		const std::string e = errorFor(name, content);
		EXPECT_NE(e.find(dir + "/" + name), std::string::npos) << e;
		EXPECT_NE(e.find(text), std::string::npos) << e;
		EXPECT_EQ(e.find('\n'), std::string::npos) << e;
	};
	expectError("empty.ini", "", "no [section]");
	expectError("comments.ini", "# only a comment\n\n", "no [section]");
	expectError("readme.md", "# vlo\n\nSome text here.\n", "line 3: 'Some text here.' is not 'key = value'");
	expectError("tum.txt", "0.0 1 2 3 0 0 0 1\n", "line 1");
	expectError("before.ini", "mode = vlo\n[pipeline]\n", "line 1: 'mode = vlo' comes before any [section]");
	expectError("noeq.ini", "[pipeline]\nmode vlo\n", "line 2: 'mode vlo' is not 'key = value'");
	expectError("binary.ini", std::string("[a]\nk = 1\n\0\x01\x02", 11), "binary content");
	expectError("header.ini", "[pipeline\nmode = vlo\n", "line 1: malformed section header");
	EXPECT_EQ(errorFor("good.ini", "# c\n; c\n[pipeline]\nmode = vlo  # why\n@define X 3\n"), "");
}
