#include <vlo/pipeline/stage_worker.h>

#include <algorithm>
#include <utility>

namespace vlo::pipeline
{
StageWorker::StageWorker(bool threaded, std::size_t depth) : depth_(std::max<std::size_t>(depth, 1))
{
	if (threaded) thread_ = std::thread([this] { serve(); });
}

StageWorker::~StageWorker()
{
	{
		std::unique_lock<std::mutex> lock(mutex_);
		changed_.wait(lock, [this] { return jobs_.empty(); });
		quitting_ = true;
	}
	changed_.notify_all();
	if (thread_.joinable()) thread_.join();
}

void StageWorker::rethrowError()
{
	if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void StageWorker::start(std::function<void()> job)
{
	if (!thread_.joinable()) return job();
	{
		std::unique_lock<std::mutex> lock(mutex_);
		changed_.wait(lock, [this] { return jobs_.size() < depth_ || error_; });
		rethrowError();
		jobs_.push_back(std::move(job));
	}
	changed_.notify_all();
}

void StageWorker::wait()
{
	std::unique_lock<std::mutex> lock(mutex_);
	changed_.wait(lock, [this] { return jobs_.empty(); });
	rethrowError();
}

void StageWorker::serve()
{
	std::unique_lock<std::mutex> lock(mutex_);
	for (;;)
	{
		changed_.wait(lock, [this] { return !jobs_.empty() || quitting_; });
		if (jobs_.empty()) return;
		auto& job = jobs_.front();
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
		if (error) error_ = error, jobs_.clear();  // what follows a failed frame must not run
		else jobs_.pop_front();
		changed_.notify_all();
	}
}
}  // namespace vlo::pipeline
