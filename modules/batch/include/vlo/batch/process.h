#pragma once
// Processes without a shell: posix_spawn with stdout/stderr redirected to files, and a pool that runs
// tasks in forked children, a few at a time.
#include <vlo/batch/jobs.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace vlo::batch
{
/// Runs one step to its end (stdin from /dev/null; out/err relative to the current folder) and returns
/// its exit code, 128 + N when killed by signal N, or 127 (message in step.err) when it cannot start.
/// Once this process is interrupted (SIGINT, SIGTERM), the step gets the same signal, and when it has
/// ended (having removed what it was writing), runStep throws Interrupted.
int runStep(const Step& step);

struct Task
{
	std::string name;
	std::function<int()> body;  ///< runs in a child process; its return value is the exit code
};

struct TaskResult
{
	std::string name;
	int exit_code = 0;
	double seconds = 0;
	bool started = false;  ///< false: vlo-batch was interrupted before its turn
	bool stopped = false;  ///< interrupted while it ran (exit code 130)
};

using TaskDone = std::function<void(const TaskResult& r, std::size_t done, std::size_t total)>;

/// Runs every task's body in its own forked child, at most `jobs` at once, in order; calls `done` in
/// the parent as each finishes. Results are in task order. An exception in a body is printed and
/// becomes exit code 125, Interrupted exit code 130.
/// Each child runs in its own process group. Once vlo-batch is interrupted (SIGINT, SIGTERM), no task
/// starts any more, the running ones get the same signal (runStep passes it on to their step), and
/// runTasks returns when they have ended: `done` is not called for those it stopped.
std::vector<TaskResult> runTasks(const std::vector<Task>& tasks, int jobs, const TaskDone& done);
}  // namespace vlo::batch
