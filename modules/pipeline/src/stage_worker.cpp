#include <vlo/pipeline/stage_worker.h>

#include <utility>

namespace vlo
{
StageWorker::StageWorker(bool threaded)
{
	if (threaded) thread_ = std::thread([this] { serve(); });
}

StageWorker::~StageWorker()
{
	{
		std::unique_lock<std::mutex> lock(mutex_);
		changed_.wait(lock, [this] { return !busy_; });
		quitting_ = true;
	}
	changed_.notify_all();
	if (thread_.joinable()) thread_.join();
}

void StageWorker::start(std::function<void()> job)
{
	if (!thread_.joinable()) return job();
	{
		const std::lock_guard<std::mutex> lock(mutex_);
		job_ = std::move(job);
		error_ = nullptr;
		busy_ = true;
	}
	changed_.notify_all();
}

void StageWorker::wait()
{
	std::unique_lock<std::mutex> lock(mutex_);
	changed_.wait(lock, [this] { return !busy_; });
	if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void StageWorker::serve()
{
	std::unique_lock<std::mutex> lock(mutex_);
	for (;;)
	{
		changed_.wait(lock, [this] { return (busy_ && job_) || quitting_; });
		if (quitting_) return;
		auto job = std::move(job_);
		job_ = nullptr;
		lock.unlock();
		std::exception_ptr error;
		try
		{
			job();
		}
		catch (...)
		{
			error = std::current_exception();
		}
		lock.lock();
		error_ = error;
		busy_ = false;
		changed_.notify_all();
	}
}
}  // namespace vlo
