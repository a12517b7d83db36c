#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <vlo/batch/process.h>

#include <chrono>
#include <filesystem>
#include <string>

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

namespace
{
long long nowNs()
{
	return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
		.count();
}
}  // namespace

TEST(BatchProcess, TasksRunInParallelAndKeepTheirOrder)
{
	// Tasks run in forked children: each writes its start and end (monotonic clock, shared by all processes) to
	// files. Tasks 2k and 2k+1 wait for each other to start, so with two jobs they overlap; one at a time, the
	// first would give up waiting (after 20 s) before the second starts and the intervals would not intersect.
	test::ScratchDir dir("parallel");
	std::vector<Task> tasks;
	for (int i = 0; i < 4; ++i)
		tasks.push_back({"t" + std::to_string(i), [i, &dir] {
							 test::writeFile(dir / ("start" + std::to_string(i)), std::to_string(nowNs()));
							 const std::string partner = dir / ("start" + std::to_string(i ^ 1));
							 for (int k = 0; k < 2000 && !std::filesystem::exists(partner); ++k) usleep(10000);
							 test::writeFile(dir / ("end" + std::to_string(i)), std::to_string(nowNs()));
							 return i;
						 }});
	tasks.push_back({"throws", []() -> int { throw std::runtime_error("boom"); }});
	std::vector<std::string> seen;
	const auto rs = runTasks(tasks, 2, [&](const TaskResult& r, std::size_t done, std::size_t total) {
		seen.push_back(r.name);
		EXPECT_EQ(done, seen.size());
		EXPECT_EQ(total, 5u);
	});
	ASSERT_EQ(rs.size(), 5u);
	std::vector<long long> start, end;
	for (int i = 0; i < 4; ++i)
	{
		EXPECT_EQ(rs[i].name, "t" + std::to_string(i));
		EXPECT_EQ(rs[i].exit_code, i);
		start.push_back(std::stoll(test::readFile(dir / ("start" + std::to_string(i)))));
		end.push_back(std::stoll(test::readFile(dir / ("end" + std::to_string(i)))));
		EXPECT_GE(rs[i].seconds, (end[i] - start[i]) * 1e-9);  // measured around the child
	}
	for (int i : {0, 2})
		EXPECT_TRUE(start[i] < end[i + 1] && start[i + 1] < end[i]) << "tasks " << i << " and " << i + 1 << " overlap";
	// Never more than two at once: no task starts while two others are running.
	for (int i = 0; i < 4; ++i)
	{
		int running = 0;
		for (int j = 0; j < 4; ++j) running += j != i && start[j] <= start[i] && start[i] < end[j];
		EXPECT_LE(running, 1) << "task " << i << " started while " << running << " others ran";
	}
	EXPECT_EQ(rs[4].exit_code, 125);
	EXPECT_EQ(seen.size(), 5u);
}
