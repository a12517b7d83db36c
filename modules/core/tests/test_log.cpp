// The process logger: one line per message in vlo's format, and the levels --verbose and --quiet show.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vlo/core/log.h>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace
{
/// What `log` writes to stderr.
template <class F>
std::string stderrOf(F&& log)
{
	const char* path = "test_log_stderr.txt";
	std::fflush(stderr);
	const int saved = dup(fileno(stderr));
	EXPECT_NE(std::freopen(path, "w", stderr), nullptr);
	log();
	std::fflush(stderr);
	dup2(saved, fileno(stderr));
	close(saved);
	std::ifstream in(path);
	std::stringstream ss;
	ss << in.rdbuf();
	std::remove(path);
	return ss.str();
}

void allLevels()
{
	using namespace mrpt::system;
	vlo::logger().logStr(LVL_DEBUG, "d");
	vlo::logger().logStr(LVL_INFO, "i");
	vlo::logger().logStr(LVL_WARN, "w");
	vlo::logger().logFmt(LVL_ERROR, "%s: %d", "file.ini", 3);
}
}  // namespace

TEST(Log, OneFormatAndTheLevelsOfEachVerbosity)
{
	vlo::setupLogging("vlo-test");
	EXPECT_EQ(stderrOf(allLevels), "vlo-test: i\nvlo-test: warning: w\nvlo-test: error: file.ini: 3\n");
	EXPECT_TRUE(vlo::infoVisible());
	vlo::setVerbosity(true, false);
	EXPECT_EQ(stderrOf(allLevels), "vlo-test: debug: d\nvlo-test: i\nvlo-test: warning: w\nvlo-test: error: file.ini: 3\n");
	vlo::setVerbosity(false, true);
	EXPECT_EQ(stderrOf(allLevels), "vlo-test: error: file.ini: 3\n");
	EXPECT_FALSE(vlo::infoVisible());
	vlo::setVerbosity(true, true);  // --quiet wins
	EXPECT_EQ(stderrOf(allLevels), "vlo-test: error: file.ini: 3\n");
	vlo::setupLogging("vlo-test");
}
