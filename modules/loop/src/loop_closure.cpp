#include <vlo/loop/keyframe.h>
#include <vlo/loop/loop_closure.h>
#include <vlo/loop/loop_worker.h>

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
		: options(o), selector(o.keyframe_distance, o.keyframe_angle_deg * M_PI / 180), worker(o)
	{
	}

	void run()
	{
		lowerThisThreadsPriority();
		for (;;)
		{
			Keyframe kf;
			{
				std::unique_lock<std::mutex> lock(mutex);
				wake.wait(lock, [&] { return stop || !queue.empty(); });
				if (queue.empty()) return;
				kf = std::move(queue.front());
				queue.pop_front();
			}
			if (error) continue;  // after a failure the rest is drained, not handled
			try
			{
				worker.process(std::move(kf));
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
	// The odometry thread's: every frame, the last frame's pose and time, the path.
	std::vector<FrameRecord> frames;
	bool has_previous = false;
	double previous_t = 0, path = 0;
	Eigen::Isometry3d previous = Eigen::Isometry3d::Identity();
	std::size_t keyframes_sent = 0;

	// Handed over under the mutex.
	std::mutex mutex;
	std::condition_variable wake;
	std::deque<Keyframe> queue;
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

void LoopClosure::addFrame(long long frame, double t, const Eigen::Isometry3d& world_T_vehicle, const PointCloud& scan,
	const Eigen::Isometry3d& vehicle_T_lidar)
{
	Impl& m = *impl_;
	if (m.has_previous) m.path += (world_T_vehicle.translation() - m.previous.translation()).norm();
	if (m.selector.take(world_T_vehicle))
	{
		Keyframe kf;
		kf.frame = frame;
		kf.t = t;
		kf.odometry = world_T_vehicle;
		kf.path = m.path;
		// The LiDAR's motion over the last frame interval, from the odometry (none for the first frame).
		const Eigen::Isometry3d motion = m.has_previous
			? Eigen::Isometry3d(vehicle_T_lidar.inverse() * m.previous.inverse() * world_T_vehicle * vehicle_T_lidar)
			: Eigen::Isometry3d::Identity();
		const double dt = m.has_previous ? t - m.previous_t : 0.0;
		kf.points = keyframeScan(scan, motion, dt, vehicle_T_lidar, m.options.scan_voxel);
		{
			std::lock_guard<std::mutex> lock(m.mutex);
			m.queue.push_back(std::move(kf));
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
