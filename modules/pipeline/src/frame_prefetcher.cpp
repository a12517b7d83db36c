#include <vlo/core/stopwatch.h>
#include <vlo/pipeline/frame_prefetcher.h>

namespace vlo::pipeline
{
FramePrefetcher::FramePrefetcher(io::RawlogReader& reader, std::size_t ahead, std::size_t limit, Prepare prepare)
	: reader_(reader), ahead_(ahead), limit_(limit), prepare_(std::move(prepare))
{
	if (ahead_ > 0) thread_ = std::thread([this] { readAhead(); });
}

FramePrefetcher::~FramePrefetcher() { stop(); }

void FramePrefetcher::stop()
{
	{
		const std::lock_guard<std::mutex> lock(mutex_);
		stopping_ = true;
	}
	changed_.notify_all();
	if (thread_.joinable()) thread_.join();
}

bool FramePrefetcher::readOne(ReadFrame& read)
{
	if (limit_ > 0 && read_ >= limit_) return false;
	if (!reader_.next(read.frame)) return false;
	++read_;
	progress_ = reader_.progress();
	if (prepare_)
	{
		const auto t0 = SteadyClock::now();
		read.prepared = prepare_(read.frame);
		read.prepared_ms = msSince(t0);
	}
	return true;
}

bool FramePrefetcher::next(ReadFrame& read)
{
	if (ahead_ == 0) return readOne(read);
	std::unique_lock<std::mutex> lock(mutex_);
	changed_.wait(lock, [this] { return !queue_.empty() || finished_; });
	if (queue_.empty())
	{
		if (error_) std::rethrow_exception(error_);
		return false;
	}
	read = std::move(queue_.front());
	queue_.pop_front();
	lock.unlock();
	changed_.notify_all();
	return true;
}

void FramePrefetcher::readAhead()
{
	for (;;)
	{
		ReadFrame read;
		bool more = false;
		std::exception_ptr error;
		try
		{
			more = readOne(read);
		}
		catch (...)
		{
			error = std::current_exception();
		}
		std::unique_lock<std::mutex> lock(mutex_);
		if (!more)
		{
			error_ = error;
			finished_ = true;
			lock.unlock();
			changed_.notify_all();
			return;
		}
		changed_.wait(lock, [this] { return queue_.size() < ahead_ || stopping_; });
		if (stopping_) return;
		queue_.push_back(std::move(read));
		lock.unlock();
		changed_.notify_all();
	}
}
}  // namespace vlo::pipeline
