#include <vlo/batch/process.h>
#include <vlo/core/log.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

extern char** environ;

namespace vlo::batch
{
namespace
{
int exitCodeOf(int status)
{
	if (WIFEXITED(status)) return WEXITSTATUS(status);
	if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
	return 1;
}
}  // namespace

int runStep(const Step& step)
{
	posix_spawn_file_actions_t fa;
	posix_spawn_file_actions_init(&fa);
	posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
	posix_spawn_file_actions_addopen(&fa, 1, step.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
	posix_spawn_file_actions_addopen(&fa, 2, step.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
	std::vector<char*> argv;
	for (const auto& a : step.argv) argv.push_back(const_cast<char*>(a.c_str()));
	argv.push_back(nullptr);
	pid_t pid = 0;
	const int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
	posix_spawn_file_actions_destroy(&fa);
	if (rc != 0)
	{
		std::ofstream(step.err) << "vlo-batch: error: cannot start " << step.argv[0] << ": " << std::strerror(rc) << "\n";
		return 127;
	}
	int status = 0;
	while (waitpid(pid, &status, 0) < 0)
		if (errno != EINTR) return 1;
	return exitCodeOf(status);
}

std::vector<TaskResult> runTasks(const std::vector<Task>& tasks, int jobs, const TaskDone& done)
{
	std::vector<TaskResult> results(tasks.size());
	std::vector<std::pair<pid_t, std::size_t>> running;  // pid, task index
	std::vector<std::chrono::steady_clock::time_point> start(tasks.size());
	std::size_t next = 0, finished = 0;
	while (finished < tasks.size())
	{
		while (next < tasks.size() && static_cast<int>(running.size()) < std::max(jobs, 1))
		{
			std::fflush(nullptr);  // or the child flushes the parent's buffered output again
			start[next] = std::chrono::steady_clock::now();
			const pid_t pid = fork();
			if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
			if (pid == 0)
			{
				int code = 125;
				try
				{
					code = tasks[next].body();
				}
				catch (const std::exception& e)
				{
					logger().logStr(mrpt::system::LVL_ERROR, tasks[next].name + ": " + e.what());
				}
				std::fflush(nullptr);
				_exit(code);  // no static destructors of the parent's state in the child
			}
			running.emplace_back(pid, next++);
		}
		int status = 0;
		const pid_t pid = waitpid(-1, &status, 0);
		if (pid < 0)
		{
			if (errno == EINTR) continue;
			throw std::runtime_error(std::string("waitpid failed: ") + std::strerror(errno));
		}
		for (auto it = running.begin(); it != running.end(); ++it)
			if (it->first == pid)
			{
				const std::size_t i = it->second;
				running.erase(it);
				results[i] = {tasks[i].name, exitCodeOf(status),
					std::chrono::duration<double>(std::chrono::steady_clock::now() - start[i]).count()};
				if (done) done(results[i], ++finished, tasks.size());
				break;
			}
	}
	return results;
}
}  // namespace vlo::batch
