#pragma once
// Bounded reorder buffer: messages come in bag (arrival) order, a scan ~0.1 s after its stamp; they
// leave in stamp order (ties: lower sensor id first) once the newest stamp seen is `window` seconds past
// theirs. Memory is bounded by what the sensors give in `window` seconds.
#include <cstddef>
#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace vlo::rosbag_io
{
template <class T>
class StampOrder
{
   public:
	using Sink = std::function<void(double stamp, int sensor, T&&)>;
	StampOrder(double window, int sensors, Sink sink)
		: window_(window), sink_(std::move(sink)), last_(sensors, -1e300)
	{
	}

	/// Queues an item of sensor 0..sensors-1; returns false (and drops it) when its stamp is not after
	/// the last one released or queued for that sensor with that stamp: it came later than the window
	/// allows, or repeats a stamp.
	bool push(double stamp, int sensor, T item)
	{
		const Key key{stamp, sensor};
		if (stamp <= last_[sensor] || pending_.count(key)) return false;
		pending_.emplace(key, std::move(item));
		if (stamp > newest_) newest_ = stamp;
		while (!pending_.empty() && pending_.begin()->first.first < newest_ - window_) releaseFirst();
		return true;
	}
	void flush()
	{
		while (!pending_.empty()) releaseFirst();
	}
	std::size_t pending() const { return pending_.size(); }

   private:
	using Key = std::pair<double, int>;
	double window_, newest_ = -1e300;
	Sink sink_;
	std::vector<double> last_;  // last released stamp per sensor
	std::map<Key, T> pending_;

	void releaseFirst()
	{
		auto node = pending_.extract(pending_.begin());
		last_[node.key().second] = node.key().first;
		sink_(node.key().first, node.key().second, std::move(node.mapped()));
	}
};
}  // namespace vlo::rosbag_io
