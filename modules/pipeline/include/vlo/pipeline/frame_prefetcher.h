#pragma once
// Reads frames ahead on a thread of its own while the run loop processes the current one, so that
// rawlog parsing, image decoding and the work done on a frame alone (a LiDAR odometry's features)
// overlap the estimators. The queue is bounded (memory stays flat),
// frames and the reader's error come out in file order, and no frame past the limit is read: a run
// sees exactly what reading on its own thread would give it, the reader's statistics included.
#include <vlo/io/rawlog_reader.h>
#include <vlo/kernel/lidar_odometry.h>

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace vlo::pipeline
{
/// A frame as read, with what the LiDAR odometry prepared of it on the reading thread.
struct ReadFrame
{
	Frame frame;
	std::unique_ptr<kernel::PreparedScan> prepared;  ///< nullptr: nothing prepared
	double prepared_ms = 0;  ///< spent in the preparation
};

class FramePrefetcher
{
   public:
	/// Work on a frame read (it may change the frame), and its result.
	using Prepare = std::function<std::unique_ptr<kernel::PreparedScan>(Frame&)>;

	/// `ahead` = frames read in advance (0: no thread, next() reads on the caller's thread);
	/// `limit` = frames to read at most (0 = all); `prepare`, if given, runs on each frame read,
	/// on the reading thread.
	FramePrefetcher(io::RawlogReader& reader, std::size_t ahead, std::size_t limit, Prepare prepare = {});
	/// Stops reading and waits for the thread.
	~FramePrefetcher();
	FramePrefetcher(const FramePrefetcher&) = delete;
	FramePrefetcher& operator=(const FramePrefetcher&) = delete;

	/// The next frame; false after the last. Rethrows the reader's exception where it occurred.
	bool next(ReadFrame& read);
	/// Fraction of the file read so far.
	double progress() const { return progress_; }
	/// Stops reading ahead; the reader may be used again (e.g. its statistics) once this returns.
	void stop();

   private:
	void readAhead();
	bool readOne(ReadFrame& read);

	io::RawlogReader& reader_;
	const std::size_t ahead_, limit_;
	const Prepare prepare_;
	std::size_t read_ = 0;  ///< frames taken from the reader
	std::atomic<double> progress_{0};
	std::mutex mutex_;
	std::condition_variable changed_;
	std::deque<ReadFrame> queue_;
	bool finished_ = false;  ///< the reader thread has nothing more to add
	bool stopping_ = false;
	std::exception_ptr error_;
	std::thread thread_;
};
}  // namespace vlo::pipeline
