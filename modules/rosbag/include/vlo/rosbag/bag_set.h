#pragma once
// One or more ROS 1 bags read as one recording (rosbag::Bag / rosbag::View from Debian's
// librosbag-storage: chunk by chunk, never the whole file). Every failure is an InputError naming the bag.
#include <vlo/core/error.h>

#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vlo::rosbag_io
{
struct TopicInfo
{
	std::string name, type;
	std::size_t messages = 0;
	double first = 0, last = 0;  ///< bag (receipt) times, seconds
	double rateHz() const { return messages > 1 && last > first ? (messages - 1) / (last - first) : 0.0; }
};

class BagSet
{
   public:
	/// Opens every bag; throws InputError naming the first one that is missing, truncated or not a bag.
	explicit BagSet(const std::vector<std::string>& paths);
	~BagSet();

	/// "a.bag" or "a.bag, b.bag": what error messages name.
	const std::string& name() const { return name_; }
	const std::vector<TopicInfo>& topics() const { return topics_; }
	std::size_t bytes() const { return bytes_; }
	/// The topic, or an InputError naming the bags and listing the topics there.
	const TopicInfo& topic(const std::string& name, const std::string& option) const;
	bool hasTopic(const std::string& name) const;
	/// `which` named, whose type is not one of `types`: InputError.
	void requireType(const TopicInfo& t, const std::vector<std::string>& types) const;

	/// Calls f for every message of `topics` in bag-time order until f returns false.
	/// progress(fraction of the bag time span) is called now and then.
	void forEach(const std::vector<std::string>& topics, const std::function<bool(const rosbag::MessageInstance&)>& f,
		const std::function<void(double)>& progress = {}) const;

   private:
	std::vector<std::unique_ptr<rosbag::Bag>> bags_;
	std::vector<TopicInfo> topics_;
	std::string name_;
	std::size_t bytes_ = 0;
};

/// Instantiates a message of type M, or an InputError naming the bag and topic.
template <class M>
boost::shared_ptr<M> instantiate(const rosbag::MessageInstance& m, const std::string& bag)
{
	auto p = m.instantiate<M>();
	if (!p) failInput(bag, "topic " + m.getTopic() + ": cannot read a " + m.getDataType() + " message as " + ros::message_traits::datatype<M>());
	return p;
}

/// ROS time of a message header in seconds.
inline double seconds(const ros::Time& t) { return t.sec + t.nsec * 1e-9; }
}  // namespace vlo::rosbag_io
