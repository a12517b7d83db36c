#include "bag_writer.h"

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_msgs/TFMessage.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

namespace vlo::test
{
namespace
{
using sensor_msgs::PointField;

ros::Time rosTime(double t) { return ros::Time(t); }

geometry_msgs::Transform toMsg(const Eigen::Isometry3d& T)
{
	geometry_msgs::Transform m;
	const Eigen::Quaterniond q(T.linear());
	m.rotation.w = q.w(), m.rotation.x = q.x(), m.rotation.y = q.y(), m.rotation.z = q.z();
	m.translation.x = T.translation().x(), m.translation.y = T.translation().y(), m.translation.z = T.translation().z();
	return m;
}

tf2_msgs::TFMessage rigTransforms(const SensorRig& rig, const BagLayout& l, double t)
{
	tf2_msgs::TFMessage tf;
	for (const auto& [child, T] : {std::pair{l.lidar_frame, rig.vehicle_T_lidar}, std::pair{l.camera_frame, rig.vehicle_T_camera}})
	{
		geometry_msgs::TransformStamped s;
		s.header.stamp = rosTime(t);
		s.header.frame_id = l.vehicle_frame;
		s.child_frame_id = child;
		s.transform = toMsg(T);
		tf.transforms.push_back(s);
	}
	return tf;
}

/// Velodyne driver layout: x y z intensity (float32), ring (uint16), time (float32); padded to 32 bytes.
sensor_msgs::PointCloud2 toCloud(const Frame& f, const BagLayout& l)
{
	sensor_msgs::PointCloud2 pc;
	pc.header.stamp = rosTime(f.t + l.stamp_offset);
	pc.header.frame_id = l.lidar_frame;
	const auto field = [&](const char* name, std::uint32_t offset, std::uint8_t type) {
		PointField pf;
		pf.name = name, pf.offset = offset, pf.datatype = type, pf.count = 1;
		pc.fields.push_back(pf);
	};
	// Fields out of offset order on purpose (the reader must go by offsets).
	field("intensity", 12, PointField::FLOAT32);
	field(l.drop_x ? "u" : "x", 0, PointField::FLOAT32);
	field("y", 4, PointField::FLOAT32);
	field("z", 8, PointField::FLOAT32);
	if (f.scan.has_ring) field("ring", 16, PointField::UINT16);
	if (f.scan.has_time) field("time", 20, PointField::FLOAT32);
	pc.point_step = 32;
	pc.height = 1;
	pc.width = static_cast<std::uint32_t>(f.scan.size());
	pc.row_step = pc.point_step * pc.width;
	pc.is_bigendian = l.big_endian;
	pc.is_dense = true;
	pc.data.assign(std::size_t(pc.row_step), 0xAB);  // padding that must be ignored
	const auto put = [&](std::uint8_t* dst, const void* src, std::size_t n) {
		std::memcpy(dst, src, n);
		if (l.big_endian) std::reverse(dst, dst + n);  // the test host is little-endian
	};
	for (std::size_t i = 0; i < f.scan.size(); ++i)
	{
		const auto& p = f.scan[i];
		std::uint8_t* d = pc.data.data() + i * pc.point_step;
		put(d + 0, &p.x, 4), put(d + 4, &p.y, 4), put(d + 8, &p.z, 4), put(d + 12, &p.intensity, 4);
		if (f.scan.has_ring) put(d + 16, &p.ring, 2);
		if (f.scan.has_time) put(d + 20, &p.time, 4);
	}
	return pc;
}

sensor_msgs::CameraInfo toCameraInfo(const Frame& f, const BagLayout& l)
{
	const auto& c = f.rig.camera;
	sensor_msgs::CameraInfo ci;
	ci.header.stamp = rosTime(f.t + l.stamp_offset);
	ci.header.frame_id = l.camera_frame;
	ci.width = c.width, ci.height = c.height;
	ci.K = {c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1};
	ci.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
	ci.P = {c.fx, 0, c.cx, 0, 0, c.fy, c.cy, 0, 0, 0, 1, 0};
	const auto& d = c.dist;
	if (c.distortion == mrpt::img::DistortionModel::kannala_brandt)
	{
		ci.distortion_model = "equidistant";
		ci.D = {d[0], d[1], d[4], d[5]};
	}
	else if (d[5] != 0 || d[6] != 0 || d[7] != 0)
	{
		ci.distortion_model = "rational_polynomial";
		ci.D.assign(d.begin(), d.end());
	}
	else
	{
		ci.distortion_model = "plumb_bob";
		ci.D.assign(d.begin(), d.begin() + 5);
	}
	if (!l.distortion_model.empty()) ci.distortion_model = l.distortion_model;
	return ci;
}

template <class M>
void fillHeader(M& m, const Frame& f, const BagLayout& l)
{
	m.header.stamp = rosTime(f.t + l.stamp_offset);
	m.header.frame_id = l.camera_frame;
}

void writeImage(rosbag::Bag& bag, const Frame& f, const BagLayout& l, const ros::Time& arrival)
{
	const cv::Mat gray = f.image.asCvMatRef();
	const std::string& e = l.image_encoding;
	if (e == "png" || e == "jpeg")
	{
		sensor_msgs::CompressedImage ci;
		fillHeader(ci, f, l);
		ci.format = "mono8; " + e + " compressed mono8";
		cv::imencode(e == "png" ? ".png" : ".jpg", gray, ci.data);
		bag.write(l.image_topic, arrival, ci);
		return;
	}
	static const std::map<std::string, std::pair<int, int>> codes = {{"mono8", {-1, 1}}, {"rgb8", {cv::COLOR_GRAY2RGB, 3}},
		{"bgr8", {cv::COLOR_GRAY2BGR, 3}}, {"rgba8", {cv::COLOR_GRAY2RGBA, 4}}, {"bgra8", {cv::COLOR_GRAY2BGRA, 4}},
		{"mono16", {-2, 2}}};
	sensor_msgs::Image im;
	fillHeader(im, f, l);
	im.encoding = e;
	im.width = gray.cols, im.height = gray.rows;
	cv::Mat out;
	const auto it = codes.find(e);
	if (it == codes.end()) out = gray;  // an unsupported encoding name over grey bytes (broken-input tests)
	else if (it->second.first == -1) out = gray;
	else if (it->second.first == -2) gray.convertTo(out, CV_16U, 257.0);  // 8-bit v -> 257 v
	else cv::cvtColor(gray, out, it->second.first);
	out = out.clone();  // continuous
	im.step = static_cast<std::uint32_t>(out.cols * out.elemSize());
	im.data.assign(out.data, out.data + im.step * out.rows);
	bag.write(l.image_topic, arrival, im);
}

void writeGroundTruth(rosbag::Bag& bag, const StampedPose& p, const BagLayout& l)
{
	const ros::Time t = rosTime(p.t + l.stamp_offset);
	const Eigen::Quaterniond q(p.pose.linear());
	geometry_msgs::Pose pose;
	pose.position.x = p.pose.translation().x(), pose.position.y = p.pose.translation().y(), pose.position.z = p.pose.translation().z();
	pose.orientation.w = q.w(), pose.orientation.x = q.x(), pose.orientation.y = q.y(), pose.orientation.z = q.z();
	const ros::Time arrival = t + ros::Duration(0.005);
	if (l.gt_type == "geometry_msgs/PoseStamped")
	{
		geometry_msgs::PoseStamped m;
		m.header.stamp = t, m.header.frame_id = "world", m.pose = pose;
		bag.write(l.gt_topic, arrival, m);
	}
	else if (l.gt_type == "geometry_msgs/PointStamped")
	{
		geometry_msgs::PointStamped m;
		m.header.stamp = t, m.header.frame_id = "world", m.point = pose.position;
		bag.write(l.gt_topic, arrival, m);
	}
	else
	{
		nav_msgs::Odometry m;
		m.header.stamp = t, m.header.frame_id = "world", m.child_frame_id = l.vehicle_frame, m.pose.pose = pose;
		bag.write(l.gt_topic, arrival, m);
	}
}
}  // namespace

void addVlp16Fields(PointCloud& scan)
{
	for (auto& p : scan)
	{
		const double elev = std::atan2(p.z, std::hypot(p.x, p.y)) * 180 / M_PI;
		p.ring = static_cast<std::uint16_t>(std::lround((15 - elev) / 2));
		p.time = static_cast<float>(std::atan2(p.y, p.x) / (2 * M_PI) * 0.1);
	}
	scan.has_ring = scan.has_time = true;
}

void writeBag(const std::string& path, const std::vector<Frame>& frames, const Trajectory& gt, const BagLayout& l)
{
	rosbag::Bag bag(path, rosbag::bagmode::Write);
	const double t0 = (frames.empty() ? 0.0 : frames.front().t) + l.stamp_offset;
	if (!frames.empty() && l.tf_static && !l.tf_as_dynamic)
		bag.write("/tf_static", rosTime(t0 + 1e-3), rigTransforms(frames.front().rig, l, t0));
	for (const auto& f : frames)
	{
		const double t = f.t + l.stamp_offset;
		if (l.tf_static && l.tf_as_dynamic) bag.write("/tf", rosTime(t + 1e-3), rigTransforms(f.rig, l, t));
		if (f.has_image)
		{
			bag.write(l.info_topic, rosTime(t + l.image_delay), toCameraInfo(f, l));
			writeImage(bag, f, l, rosTime(t + l.image_delay));
		}
		if (f.has_scan) bag.write(l.lidar_topic, rosTime(t + l.scan_delay), toCloud(f, l));
	}
	for (const auto& p : gt) writeGroundTruth(bag, p, l);
	bag.close();
}
}  // namespace vlo::test
