#include <vlo/pipeline/frame_prefetcher.h>

namespace vlo
{
FramePrefetcher::FramePrefetcher(RawlogReader& reader, std::size_t ahead, std::size_t limit, std::function<void(Frame&)> prepare)
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

bool FramePrefetcher::readOne(Frame& frame)
{
	if (limit_ > 0 && read_ >= limit_) return false;
	if (!reader_.next(frame)) return false;
	++read_;
	progress_ = reader_.progress();
	if (prepare_) prepare_(frame);
	return true;
}

bool FramePrefetcher::next(Frame& frame)
{
	if (ahead_ == 0) return readOne(frame);
	std::unique_lock<std::mutex> lock(mutex_);
	changed_.wait(lock, [this] { return !queue_.empty() || finished_; });
	if (queue_.empty())
	{
		if (error_) std::rethrow_exception(error_);
		return false;
	}
	frame = std::move(queue_.front());
	queue_.pop_front();
	lock.unlock();
	changed_.notify_all();
	return true;
}

void FramePrefetcher::readAhead()
{
	for (;;)
	{
		Frame frame;
		bool more = false;
		std::exception_ptr error;
		try
		{
			more = readOne(frame);
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
		queue_.push_back(std::move(frame));
		lock.unlock();
		changed_.notify_all();
	}
}
}  // namespace vlo
