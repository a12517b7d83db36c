#pragma once
// Runs one job at a time beside the caller: the run loop hands it the LiDAR odometry of frame i and
// runs the motion source of frame i+1 itself, then waits for both. Without a thread the job runs
// inline in start(), so one and two threads do the same work in the same order per module.
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace vlo
{
class StageWorker
{
   public:
	explicit StageWorker(bool threaded);
	/// Waits for a running job (its error is dropped: this runs while another one unwinds) and ends
	/// the thread.
	~StageWorker();
	StageWorker(const StageWorker&) = delete;
	StageWorker& operator=(const StageWorker&) = delete;

	/// Starts `job`; the previous one must have been waited for. Inline: runs it now, and its
	/// exception propagates from here.
	void start(std::function<void()> job);
	/// Waits for the job started last; rethrows its exception.
	void wait();

   private:
	void serve();

	std::mutex mutex_;
	std::condition_variable changed_;
	std::function<void()> job_;
	bool busy_ = false, quitting_ = false;
	std::exception_ptr error_;
	std::thread thread_;
};
}  // namespace vlo
