#include <vlo/core/error.h>
#include <vlo/rosbag/bag_set.h>
#include <vlo/rosbag/pointcloud2.h>

#include <sensor_msgs/PointField.h>

#include <cmath>
#include <cstring>
#include <optional>

namespace vlo::rosbag_io
{
namespace
{
using sensor_msgs::PointField;

std::size_t sizeOf(std::uint8_t datatype)
{
	switch (datatype)
	{
		case PointField::INT8:
		case PointField::UINT8: return 1;
		case PointField::INT16:
		case PointField::UINT16: return 2;
		case PointField::INT32:
		case PointField::UINT32:
		case PointField::FLOAT32: return 4;
		case PointField::FLOAT64: return 8;
		default: return 0;
	}
}

/// Reads one field of any datatype and byte order as a double.
struct FieldReader
{
	std::uint32_t offset = 0;
	std::uint8_t datatype = 0;
	bool swap = false;

	template <class V>
	V load(const std::uint8_t* p) const
	{
		std::uint8_t b[sizeof(V)];
		std::memcpy(b, p + offset, sizeof(V));
		if (swap)
			for (std::size_t i = 0; i < sizeof(V) / 2; ++i) std::swap(b[i], b[sizeof(V) - 1 - i]);
		V v;
		std::memcpy(&v, b, sizeof(V));
		return v;
	}
	double operator()(const std::uint8_t* p) const
	{
		switch (datatype)
		{
			case PointField::INT8: return load<std::int8_t>(p);
			case PointField::UINT8: return load<std::uint8_t>(p);
			case PointField::INT16: return load<std::int16_t>(p);
			case PointField::UINT16: return load<std::uint16_t>(p);
			case PointField::INT32: return load<std::int32_t>(p);
			case PointField::UINT32: return load<std::uint32_t>(p);
			case PointField::FLOAT32: return load<float>(p);
			default: return load<double>(p);
		}
	}
};

class Layout
{
   public:
	Layout(const sensor_msgs::PointCloud2& msg, const std::string& where) : msg_(msg), where_(where)
	{
		std::string names;
		for (const auto& f : msg.fields) names += (names.empty() ? "" : " ") + f.name;
		fields_ = names;
	}
	/// The first of `names` that the message has.
	std::optional<FieldReader> find(std::initializer_list<const char*> names, std::string* found = nullptr) const
	{
		static const bool host_big = [] {
			const std::uint16_t one = 1;
			std::uint8_t b;
			std::memcpy(&b, &one, 1);
			return b == 0;
		}();
		for (const char* name : names)
			for (const auto& f : msg_.fields)
			{
				if (f.name != name) continue;
				const std::size_t size = sizeOf(f.datatype);
				if (size == 0)
					failInput(where_, "PointCloud2 field '" + f.name + "' has unknown datatype " + std::to_string(f.datatype));
				if (f.offset + size > msg_.point_step)
					failInput(where_,
						"PointCloud2 field '" + f.name + "' at offset " + std::to_string(f.offset) +
							" does not fit point_step " + std::to_string(msg_.point_step));
				if (found) *found = name;
				return FieldReader{f.offset, f.datatype, msg_.is_bigendian != host_big};
			}
		return std::nullopt;
	}
	FieldReader require(const char* name) const
	{
		const auto r = find({name});
		if (!r) failInput(where_, "PointCloud2 without field '" + std::string(name) + "' (fields: " + fields_ + ")");
		return *r;
	}

   private:
	const sensor_msgs::PointCloud2& msg_;
	std::string where_, fields_;
};
}  // namespace

io::ScanReading decodePointCloud2(const sensor_msgs::PointCloud2& msg, const std::string& where)
{
	const Layout layout(msg, where);
	const FieldReader x = layout.require("x"), y = layout.require("y"), z = layout.require("z");
	const auto intensity = layout.find({"intensity", "reflectivity"});
	const auto ring = layout.find({"ring", "line"});
	std::string time_name;
	const auto time = layout.find({"time", "t", "timestamp"}, &time_name);

	const std::size_t w = msg.width, h = msg.height, step = msg.point_step;
	if (step == 0 || w * step > msg.row_step || h * std::size_t(msg.row_step) > msg.data.size())
		failInput(where,
			"PointCloud2 of " + std::to_string(w) + "x" + std::to_string(h) + " points, point_step " +
				std::to_string(step) + ", row_step " + std::to_string(msg.row_step) + " does not fit its " +
				std::to_string(msg.data.size()) + " bytes");

	const double stamp = seconds(msg.header.stamp);
	// Time as seconds from the stamp: "time" is that already, Ouster's "t" is ns, "timestamp" absolute.
	double time_scale = time_name == "t" ? 1e-9 : 1.0, time_offset = time_name == "timestamp" ? -stamp : 0.0;

	io::ScanReading out;
	out.points.has_ring = ring.has_value();
	out.points.has_time = time.has_value();
	out.points.reserve(w * h);
	for (std::size_t r = 0; r < h; ++r)
	{
		const std::uint8_t* row = msg.data.data() + r * msg.row_step;
		for (std::size_t c = 0; c < w; ++c)
		{
			const std::uint8_t* p = row + c * step;
			LidarPoint q;
			q.x = static_cast<float>(x(p));
			q.y = static_cast<float>(y(p));
			q.z = static_cast<float>(z(p));
			if (intensity) q.intensity = static_cast<float>((*intensity)(p));
			if (time)
			{
				double v = (*time)(p);
				if (time_name == "timestamp" && out.points.empty() && out.dropped == 0 &&
					std::abs(v - stamp) > 1e6 && std::abs(v * 1e-9 - stamp) < 1e3)
					time_scale = 1e-9;  // Livox drivers write nanoseconds under this name
				q.time = static_cast<float>(v * time_scale + time_offset);
			}
			if (ring)
			{
				const double v = (*ring)(p);
				if (!(v >= 0 && v <= 65535))
					failInput(where, "PointCloud2 ring value " + std::to_string(v) + " is not a laser index");
				q.ring = static_cast<std::uint16_t>(v);
			}
			if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.time))
			{
				++out.dropped;
				continue;
			}
			out.points.push_back(q);
		}
	}
	if (out.points.has_ring) io::orderRingsByElevation(out.points);
	return out;
}
}  // namespace vlo::rosbag_io
