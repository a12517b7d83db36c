#include <vlo/core/units.h>
#include <vlo/loop/keyframe.h>
#include <vlo/loop/loop_closure.h>
#include <vlo/loop/loop_worker.h>
#include <vlo/loop/odometry_chain.h>

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace vlo::loop
{
namespace
{
/// What corrected() needs of every frame.
struct FrameRecord
{
	double t = 0;
	Eigen::Isometry3d odometry = Eigen::Isometry3d::Identity();
	std::size_t keyframe = 0;  ///< the last keyframe at or before the frame
};

void lowerThisThreadsPriority()
{
#ifdef __linux__
	// The odometry runs on its own core and must not wait: the loop thread yields to it. Failure
	// (a container without the right) only leaves the priority as it was.
	(void)setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
}

/// A keyframe on its way to the loop thread: its scan still as the sensor gave it (thinned and
/// de-skewed there), or already thinned when the loop thread was behind.
struct PendingKeyframe
{
	Keyframe keyframe;
	PointCloud scan;
	Eigen::Isometry3d lidar_motion = Eigen::Isometry3d::Identity(), vehicle_T_lidar = Eigen::Isometry3d::Identity();
	double dt = 0;
};

// Raw scans waiting beyond this many (3 MB each for an HDL-64), the odometry's thread thins the next
// ones itself: the memory stays bounded, and the points are the same either way.
constexpr std::size_t kMaxRawBacklog = 16;

Eigen::Isometry3d blend(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double f)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::Quaterniond(a.linear()).slerp(f, Eigen::Quaterniond(b.linear())).toRotationMatrix();
	T.translation() = (1 - f) * a.translation() + f * b.translation();
	return T;
}
}  // namespace

struct LoopClosure::Impl
{
	explicit Impl(const LoopOptions& o)
		: options(o), selector(o.keyframe_distance, o.keyframe_angle_deg * kRadPerDeg), chain(o), worker(o)
	{
	}

	void run()
	{
		lowerThisThreadsPriority();
		for (;;)
		{
			PendingKeyframe next;
			{
				std::unique_lock<std::mutex> lock(mutex);
				wake.wait(lock, [&] { return stop || !queue.empty(); });
				if (queue.empty()) return;
				next = std::move(queue.front());
				queue.pop_front();
				if (!next.scan.empty()) --raw_backlog;
			}
			if (error) continue;  // after a failure the rest is drained, not handled
			try
			{
				if (!next.scan.empty())
					next.keyframe.points =
						keyframeScan(next.scan, next.lidar_motion, next.dt, next.vehicle_T_lidar, options.scan_voxel);
				worker.process(std::move(next.keyframe));
			}
			catch (...)
			{
				error = std::current_exception();
			}
		}
	}

	void join()
	{
		{
			std::lock_guard<std::mutex> lock(mutex);
			stop = true;
		}
		wake.notify_one();
		if (thread.joinable()) thread.join();
	}

	const LoopOptions options;
	KeyframeSelector selector;
	OdometryChain chain;  ///< the odometry's covariance since the last keyframe
	// The odometry thread's: every frame, the last frame's pose and time, the path.
	std::vector<FrameRecord> frames;
	bool has_previous = false;
	double previous_t = 0, path = 0;
	Eigen::Isometry3d previous = Eigen::Isometry3d::Identity();
	std::size_t keyframes_sent = 0;

	// Handed over under the mutex.
	std::mutex mutex;
	std::condition_variable wake;
	std::deque<PendingKeyframe> queue;
	std::size_t raw_backlog = 0;  ///< queued keyframes whose scans are not thinned yet
	bool stop = false;

	// The loop thread's until it is joined.
	LoopWorker worker;
	std::exception_ptr error;
	std::thread thread;

	bool finished = false;
	double final_seconds = 0;
};

LoopClosure::LoopClosure(const LoopOptions& options)
{
	options.validate();  // options set in code: OptionError here, not a crash on the loop thread
	impl_ = std::make_unique<Impl>(options);
	impl_->thread = std::thread([this] { impl_->run(); });
}

LoopClosure::~LoopClosure() { impl_->join(); }

void LoopClosure::addFrame(long long frame, double t, const Eigen::Isometry3d& world_T_vehicle,
	const std::optional<Matrix6d>& information, const PointCloud& scan, const Eigen::Isometry3d& vehicle_T_lidar)
{
	Impl& m = *impl_;
	if (m.has_previous)
	{
		m.path += (world_T_vehicle.translation() - m.previous.translation()).norm();
		m.chain.add(m.previous.inverse() * world_T_vehicle, information);
	}
	if (m.selector.take(world_T_vehicle))
	{
		PendingKeyframe next;
		Keyframe& kf = next.keyframe;
		kf.frame = frame;
		kf.t = t;
		kf.odometry = world_T_vehicle;
		kf.path = m.path;
		kf.odometry_covariance = m.chain.take();
		// The LiDAR's motion over the last frame interval, from the odometry (none for the first frame).
		if (m.has_previous)
		{
			next.lidar_motion = vehicle_T_lidar.inverse() * m.previous.inverse() * world_T_vehicle * vehicle_T_lidar;
			next.dt = t - m.previous_t;
		}
		next.vehicle_T_lidar = vehicle_T_lidar;
		bool behind = false;
		{
			std::lock_guard<std::mutex> lock(m.mutex);
			behind = m.raw_backlog >= kMaxRawBacklog;
		}
		// A copy of the scan costs a fraction of its thinning: the odometry's thread only copies.
		if (behind || scan.empty())
			kf.points = keyframeScan(scan, next.lidar_motion, next.dt, vehicle_T_lidar, m.options.scan_voxel);
		else
			next.scan = scan;
		{
			std::lock_guard<std::mutex> lock(m.mutex);
			if (!next.scan.empty()) ++m.raw_backlog;
			m.queue.push_back(std::move(next));
		}
		m.wake.notify_one();
		++m.keyframes_sent;
	}
	m.frames.push_back({t, world_T_vehicle, m.keyframes_sent - 1});
	m.has_previous = true;
	m.previous = world_T_vehicle;
	m.previous_t = t;
}

void LoopClosure::finish()
{
	Impl& m = *impl_;
	if (m.finished) return;
	m.join();
	m.finished = true;
	if (m.error) std::rethrow_exception(m.error);
	m.final_seconds = m.worker.finalOptimisation();
}

Trajectory LoopClosure::corrected() const
{
	const Impl& m = *impl_;
	Trajectory out;
	out.reserve(m.frames.size());
	const auto& keyframes = m.worker.keyframes();
	if (!m.finished || !m.worker.closed() || keyframes.size() != m.keyframes_sent)
	{
		for (const auto& f : m.frames) out.push_back({f.t, f.odometry});
		return out;
	}
	// Each frame moved with its keyframe's correction, blended towards the next keyframe's by time.
	const auto through = [&](std::size_t k, const Eigen::Isometry3d& odometry) {
		return Eigen::Isometry3d(m.worker.corrected(k) * keyframes[k].odometry.inverse() * odometry);
	};
	for (const auto& f : m.frames)
	{
		const std::size_t k = f.keyframe;
		Eigen::Isometry3d pose = through(k, f.odometry);
		if (k + 1 < keyframes.size())
		{
			const double span = keyframes[k + 1].t - keyframes[k].t;
			if (span > 0) pose = blend(pose, through(k + 1, f.odometry), std::clamp((f.t - keyframes[k].t) / span, 0.0, 1.0));
		}
		out.push_back({f.t, pose});
	}
	return out;
}

const std::vector<LoopRecord>& LoopClosure::loops() const { return impl_->worker.loops(); }
std::size_t LoopClosure::keyframes() const { return impl_->keyframes_sent; }
double LoopClosure::finalOptimisationSeconds() const { return impl_->final_seconds; }
}  // namespace vlo::loop
