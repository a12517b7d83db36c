#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/kernel/run_config.h>
#include <vlo_test/demo_options.h>

#include <fstream>

using namespace vlo;
using namespace vlo::kernel;

using test::DemoOptions;
using test::errorOf;

TEST(RunConfig, LoadsValuesAndOverridesAndWritesEffectiveIni)
{
	auto cfg = RunConfig::fromString("@define G 0.75\n[demo]\ncount = 7\ngain = ${G}\n", "a.ini", {"demo.mode=slow"});
	DemoOptions o;
	cfg.load(o, "demo");
	EXPECT_EQ(o.count, 7);
	EXPECT_DOUBLE_EQ(o.gain, 0.75);
	EXPECT_EQ(o.mode, "slow");
	EXPECT_NO_THROW(cfg.checkAllKeysUsed());
	const std::string eff = cfg.effectiveIni();
	EXPECT_NE(eff.find("count"), std::string::npos);
	EXPECT_NE(eff.find("table"), std::string::npos);  // defaults are written too
}

TEST(RunConfig, DottedSectionOverride)
{
	auto cfg = RunConfig::fromString("", "a.ini", {"loam.odometry.count=3"});
	DemoOptions o;
	cfg.load(o, "loam.odometry");
	EXPECT_EQ(o.count, 3);
}

/// The message of loading `ini` with `sets` into [demo] and checking every key.
std::string loadError(const std::string& ini, const std::vector<std::string>& sets = {})
{
	return errorOf([&] {
		auto cfg = RunConfig::fromString(ini, "a.ini", sets);
		DemoOptions o;
		cfg.load(o, "demo");
		cfg.checkAllKeysUsed();
	});
}

TEST(RunConfig, EveryOptionErrorNamesItsOriginSectionAndKey)
{
	// Values from the file name the file, the section and the key; values from --set name the --set,
	// also when the file has the same key.
	for (const auto& [line, problem] : test::kRefusedDemoLines)
	{
		const std::string key = test::keyOf(line), value = line.substr(key.size() + 3);
		EXPECT_EQ(loadError("[demo]\n" + line + "\n"), "a.ini: [demo] " + key + ": " + problem);
		EXPECT_EQ(loadError("[demo]\n" + key + " = 1\n", {"demo." + key + "=" + value}),
			"--set demo." + key + "=" + value + ": " + problem);
	}
	EXPECT_EQ(loadError("[demo]\ncount = 1\ngain = 1\n"), "a.ini: [demo] gain: must be below count");
	EXPECT_EQ(loadError("[demo]\ncountt = 7\n"), "a.ini: unknown key 'countt' in section [demo] (did you mean count?)");
	EXPECT_EQ(loadError("[demoo]\ncount = 7\n"), "a.ini: unknown section [demoo] (did you mean demo?)");
	EXPECT_EQ(loadError("[demo]\nsomething_else = 7\n"), "a.ini: unknown key 'something_else' in section [demo]");
	// Unknown names from --set name the --set.
	EXPECT_EQ(loadError("", {"demo.countt=7"}), "--set demo.countt=7: unknown key 'countt' in section [demo] (did you mean count?)");
	EXPECT_EQ(loadError("", {"demoo.count=7"}), "--set demoo.count=7: unknown section [demoo] (did you mean demo?)");
	EXPECT_FALSE(errorOf([] { RunConfig::fromString("", "a.ini", {"nodot=1"}); }).empty());
	// A relation broken by a --set value is blamed on the key it names.
	EXPECT_EQ(loadError("[demo]\ncount = 1\n", {"demo.gain=1"}), "--set demo.gain=1: must be below count");
	EXPECT_EQ(loadError("[demo]\ngain = 1\n", {"demo.count=1"}), "a.ini: [demo] gain: must be below count");
	// A control byte in a key is shown as '?', so that the message stays one printable line.
	EXPECT_EQ(loadError("[demo]\nco\x01unt = 1\n"), "a.ini: unknown key 'co?unt' in section [demo] (did you mean count?)");
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

// Issue 34, defect 2: MRPT keeps the last of a key given twice and merges a section given twice, silently;
// vlo-batch refused them in plans, vlo-run took them.
TEST(RunConfig, AKeyOrASectionGivenTwiceIsRefused)
{
	const std::string dir = ::testing::TempDir();
	const auto errorFor = [&](const std::string& name, const std::string& content) {
		std::ofstream(dir + "/" + name) << content;
		return errorOf([&] { RunConfig::fromFile(dir + "/" + name); });
	};
	EXPECT_EQ(errorFor("twice_key.ini", "[pipeline]\nmode = vlo\n[loam]\nmode = lo\n"), "");  // other sections
	EXPECT_NE(errorFor("twice_key.ini", "[pipeline]\nmode = vlo\n# c\nmode = lo\n")
				  .find(dir + "/twice_key.ini: line 4: [pipeline] mode: given twice"),
		std::string::npos);
	EXPECT_NE(errorFor("twice_section.ini", "[pipeline]\nmode = vlo\n[loam]\n[ pipeline ]\nthreads = 1\n")
				  .find(dir + "/twice_section.ini: line 4: section [pipeline] given twice (also line 1"),
		std::string::npos);
}

// Issue 34, defect 4: a directory given as the INI said "no [section]".
TEST(RunConfig, ADirectoryIsSaidToBeOne)
{
	const std::string e = errorOf([&] { RunConfig::fromFile(::testing::TempDir()); });
	EXPECT_NE(e.find("is a directory, expected a file"), std::string::npos) << e;
}
