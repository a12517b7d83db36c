#pragma once
// Runs jobs in order beside the caller: the run loop hands it the LiDAR odometry of each frame and
// runs the motion source of the next frames itself. Up to `depth` jobs wait or run at once, so a
// long frame on one side does not idle the other (no barrier per frame). Without a thread each job
// runs inline in start(), so one and two threads do the same work in the same order per module.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace vlo::pipeline
{
class StageWorker
{
   public:
	explicit StageWorker(bool threaded, std::size_t depth = 1);
	/// Waits for the jobs started (their error is dropped: this runs while another one unwinds) and
	/// ends the thread.
	~StageWorker();
	StageWorker(const StageWorker&) = delete;
	StageWorker& operator=(const StageWorker&) = delete;

	/// Queues `job`, first waiting while `depth` jobs are queued or running; rethrows the error of an
	/// earlier job (the jobs after a failed one are dropped). Inline: runs it now, and its exception
	/// propagates from here.
	void start(std::function<void()> job);
	/// Waits for every job started; rethrows the error of one that failed.
	void wait();

   private:
	void serve();
	void rethrowError();

	std::mutex mutex_;
	std::condition_variable changed_;
	std::deque<std::function<void()>> jobs_;  ///< the front one is running or next
	std::size_t depth_;
	bool quitting_ = false;
	std::exception_ptr error_;
	std::thread thread_;
};
}  // namespace vlo::pipeline
