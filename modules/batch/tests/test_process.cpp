#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <vlo/batch/process.h>

#include <chrono>

using namespace vlo;
using namespace vlo::batch;

TEST(BatchProcess, RunStepRedirectsAndReportsExitCodes)
{
	test::ScratchDir dir("process");
	const std::string o = dir / "o", e = dir / "e";
	EXPECT_EQ(runStep({{"/bin/sh", "-c", "echo out; echo err >&2; exit 3", "ignored"}, o, e}), 3);
	EXPECT_EQ(test::readFile(o), "out\n");
	EXPECT_EQ(test::readFile(e), "err\n");
	EXPECT_EQ(runStep({{"/bin/sh", "-c", "kill -9 $$"}, o, e}), 128 + 9);
	EXPECT_EQ(runStep({{"/bin/sh", "-c", "read x; echo \"[$x]\""}, o, e}), 0);  // stdin is /dev/null
	EXPECT_EQ(test::readFile(o), "[]\n");
	// Arguments reach the program as they are: no shell in between.
	EXPECT_EQ(runStep({{"/bin/echo", "$HOME", "a b", "'q'"}, o, e}), 0);
	EXPECT_EQ(test::readFile(o), "$HOME a b 'q'\n");
	EXPECT_EQ(runStep({{dir / "missing-tool"}, o, e}), 127);
	EXPECT_NE(test::readFile(e).find("cannot start"), std::string::npos);
}

TEST(BatchProcess, TasksRunInParallelAndKeepTheirOrder)
{
	std::vector<Task> tasks;
	for (int i = 0; i < 4; ++i)
		tasks.push_back({"t" + std::to_string(i), [i] {
							 usleep(300000);
							 return i;
						 }});
	tasks.push_back({"throws", []() -> int { throw std::runtime_error("boom"); }});
	std::vector<std::string> seen;
	const auto t0 = std::chrono::steady_clock::now();
	const auto rs = runTasks(tasks, 2, [&](const TaskResult& r, std::size_t done, std::size_t total) {
		seen.push_back(r.name);
		EXPECT_EQ(done, seen.size());
		EXPECT_EQ(total, 5u);
	});
	const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	EXPECT_LT(s, 1.1);  // 4 x 0.3 s two at a time: 0.6 s (one at a time: 1.2 s)
	EXPECT_GT(s, 0.55);
	ASSERT_EQ(rs.size(), 5u);
	for (int i = 0; i < 4; ++i)
	{
		EXPECT_EQ(rs[i].name, "t" + std::to_string(i));
		EXPECT_EQ(rs[i].exit_code, i);
		EXPECT_GT(rs[i].seconds, 0.25);
	}
	EXPECT_EQ(rs[4].exit_code, 125);
	EXPECT_EQ(seen.size(), 5u);
}
