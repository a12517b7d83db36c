#include <vlo/batch/process.h>
#include <vlo/core/interrupt.h>
#include <vlo/core/log.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>

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

/// waitpid(pid) that also returns, with 0, once a signal has interrupted this process: the handler
/// restarts a blocking waitpid, which would sleep through the signal until the child ends on its own.
pid_t waitUnlessInterrupted(pid_t pid, int& status)
{
	for (;;)
	{
		const pid_t r = waitpid(pid, &status, WNOHANG);
		if (r < 0 && errno == EINTR) continue;
		if (r != 0 || interruptSignal() != 0) return r;
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
}

pid_t waitBlocking(pid_t pid, int& status)
{
	pid_t r;
	while ((r = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {}
	return r;
}

/// In a task's child: its own process group, so that a Ctrl-C at the terminal reaches vlo-batch alone,
/// which passes it on once (a second signal would end a step at once, before it removes its outputs);
/// and SIGTERM when vlo-batch dies without passing anything on (kill -9).
void detachTaskChild(pid_t parent)
{
	setpgid(0, 0);
	prctl(PR_SET_PDEATHSIG, SIGTERM);
	if (getppid() != parent) raise(SIGTERM);  // the parent died before prctl
}
}  // namespace

int runStep(const Step& step)
{
	throwIfInterrupted();
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
	pid_t r = waitUnlessInterrupted(pid, status);
	if (r == 0)  // interrupted: the step stops too, removing what it was writing
	{
		kill(pid, interruptSignal());
		r = waitBlocking(pid, status);
	}
	if (r < 0) return 1;
	throwIfInterrupted();
	return exitCodeOf(status);
}

std::vector<TaskResult> runTasks(const std::vector<Task>& tasks, int jobs, const TaskDone& done)
{
	std::vector<TaskResult> results(tasks.size());
	for (std::size_t i = 0; i < tasks.size(); ++i) results[i].name = tasks[i].name;
	std::vector<std::pair<pid_t, std::size_t>> running;  // pid, task index
	std::vector<std::chrono::steady_clock::time_point> start(tasks.size());
	std::size_t next = 0, finished = 0;
	const pid_t self = getpid();
	bool passedOn = false;  // the signal that interrupted vlo-batch, to the running tasks
	while (!running.empty() || (next < tasks.size() && interruptSignal() == 0))
	{
		while (next < tasks.size() && static_cast<int>(running.size()) < std::max(jobs, 1) && interruptSignal() == 0)
		{
			std::fflush(nullptr);  // or the child flushes the parent's buffered output again
			start[next] = std::chrono::steady_clock::now();
			const pid_t pid = fork();
			if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
			if (pid == 0)
			{
				detachTaskChild(self);
				int code = 125;
				try
				{
					code = tasks[next].body();
				}
				catch (const Interrupted&)
				{
					code = 130;
				}
				catch (const std::exception& e)
				{
					logger().logStr(mrpt::system::LVL_ERROR, tasks[next].name + ": " + e.what());
				}
				std::fflush(nullptr);
				_exit(code);  // no static destructors of the parent's state in the child
			}
			setpgid(pid, pid);  // as the child does: whichever runs first
			results[next].started = true;
			running.emplace_back(pid, next++);
		}
		int status = 0;
		const pid_t pid = passedOn ? waitBlocking(-1, status) : waitUnlessInterrupted(-1, status);
		if (pid == 0)
		{
			for (const auto& r : running) kill(r.first, interruptSignal());
			passedOn = true;
			continue;
		}
		if (pid < 0) throw std::runtime_error(std::string("waitpid failed: ") + std::strerror(errno));
		for (auto it = running.begin(); it != running.end(); ++it)
			if (it->first == pid)
			{
				const std::size_t i = it->second;
				running.erase(it);
				results[i].exit_code = exitCodeOf(status);
				results[i].seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start[i]).count();
				results[i].stopped = passedOn && results[i].exit_code == 130;
				++finished;
				if (done && !results[i].stopped) done(results[i], finished, tasks.size());
				break;
			}
	}
	return results;
}
}  // namespace vlo::batch
