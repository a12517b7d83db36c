#include <vlo/core/input_file.h>
#include <vlo/core/interrupt.h>
#include <vlo/rosbag/bag_set.h>
#include <vlo/rosbag/bag_structure.h>

#include <console_bridge/console.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace vlo::rosbag_io
{
namespace
{
std::string join(const std::vector<std::string>& v)
{
	std::string s;
	for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
	return s;
}
}  // namespace

BagSet::BagSet(const std::vector<std::string>& paths)
{
	// rosbag reports through console_bridge on stderr; vlo reports its errors itself, in one line.
	console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
	if (paths.empty()) failInput("command line", "no --bag given");
	name_ = join(paths);
	std::map<std::string, TopicInfo> topics;
	for (const auto& path : paths)
	{
		requireInputFile(path);
		std::error_code ec;
		bytes_ += std::filesystem::file_size(path, ec);
		checkBagStructure(path);
		try
		{
			bags_.push_back(std::make_unique<rosbag::Bag>(path, rosbag::bagmode::Read));
			rosbag::View all(*bags_.back());
			for (const auto* c : all.getConnections())
			{
				auto& t = topics[c->topic];
				if (!t.type.empty() && t.type != c->datatype)
					failInput(path, "topic " + c->topic + " is a " + c->datatype + " here and a " + t.type + " elsewhere");
				if (!t.name.empty()) continue;
				t.name = c->topic;
				t.type = c->datatype;
			}
			for (auto& [name, t] : topics)
			{
				rosbag::View v(*bags_.back(), rosbag::TopicQuery(name));
				const std::size_t n = v.size();
				if (n == 0) continue;
				const double first = seconds(v.getBeginTime()), last = seconds(v.getEndTime());
				t.first = t.messages ? std::min(t.first, first) : first;
				t.last = t.messages ? std::max(t.last, last) : last;
				t.messages += n;
			}
		}
		catch (const rosbag::BagException& e)
		{
			failInput(path, std::string("not a readable ROS 1 bag (truncated or corrupt?): ") + e.what());
		}
	}
	for (auto& [name, t] : topics) topics_.push_back(t);
}

BagSet::~BagSet() = default;

bool BagSet::hasTopic(const std::string& name) const
{
	return std::any_of(topics_.begin(), topics_.end(), [&](const TopicInfo& t) { return t.name == name; });
}

const TopicInfo& BagSet::topic(const std::string& name, const std::string& option) const
{
	for (const auto& t : topics_)
		if (t.name == name) return t;
	std::vector<std::string> there;
	for (const auto& t : topics_) there.push_back(t.name);
	failInput(name_, option + ": no topic '" + name + "' (topics there: " + join(there) + ")");
}

void BagSet::requireType(const TopicInfo& t, const std::vector<std::string>& types) const
{
	if (std::find(types.begin(), types.end(), t.type) == types.end())
		failInput(name_, "topic " + t.name + " is a " + t.type + ", expected " + join(types));
}

void BagSet::forEach(const std::vector<std::string>& topics, const std::function<bool(const rosbag::MessageInstance&)>& f,
	const std::function<void(double)>& progress) const
{
	try
	{
		rosbag::View view;
		for (const auto& b : bags_) view.addQuery(*b, rosbag::TopicQuery(topics));
		const double begin = seconds(view.getBeginTime()), span = seconds(view.getEndTime()) - begin;
		std::size_t n = 0;
		for (const auto& m : view)
		{
			throwIfInterrupted();  // at every message: a bag of fewer than 64 never reaches the progress line
			if (!f(m)) break;
			if (progress && ++n % 64 == 0) progress(span > 0 ? (seconds(m.getTime()) - begin) / span : 0.0);
		}
	}
	catch (const rosbag::BagException& e)
	{
		failInput(name_, std::string("cannot read (truncated or corrupt?): ") + e.what());
	}
	catch (const ros::Exception& e)  // deserialisation of a message that does not fit its type
	{
		failInput(name_, std::string("cannot read a message: ") + e.what());
	}
}
}  // namespace vlo::rosbag_io
