#include <vlo/core/error.h>
#include <vlo/core/progress.h>
#include <vlo/core/stopwatch.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/rawlog_writer.h>
#include <vlo/io/trajectory.h>
#include <vlo/rosbag/bag_set.h>
#include <vlo/rosbag/camera_info.h>
#include <vlo/rosbag/extrinsics_file.h>
#include <vlo/rosbag/image_msg.h>
#include <vlo/rosbag/pointcloud2.h>
#include <vlo/rosbag/rosbag_import.h>
#include <vlo/rosbag/stamp_order.h>
#include <vlo/rosbag/transform_tree.h>

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/CameraInfo.h>
#include <tf2_msgs/TFMessage.h>

#include <boost/make_shared.hpp>

#include <algorithm>
#include <cstdio>
#include <ostream>

namespace vlo::rosbag_io
{
using namespace rosbag_io;

namespace
{
const char* kPointCloud2 = "sensor_msgs/PointCloud2";
const char* kImage = "sensor_msgs/Image";
const char* kCompressed = "sensor_msgs/CompressedImage";
const char* kTfHint = "give --extrinsics FILE.yaml (lidar_T_camera: [16 numbers], camera optical frame in LiDAR frame)";

std::string parentNamespace(const std::string& topic)
{
	const auto slash = topic.find_last_of('/');
	return slash == std::string::npos ? "" : topic.substr(0, slash);
}

/// The CameraInfo topic beside the image topic: "<ns>/camera_info" for the image's namespace and each
/// one above it (".../image_raw/compressed" -> ".../camera_info").
std::string cameraInfoTopicFor(const BagSet& bags, const std::string& image_topic)
{
	std::string tried;
	for (std::string ns = parentNamespace(image_topic);; ns = parentNamespace(ns))
	{
		const std::string candidate = ns + "/camera_info";
		if (bags.hasTopic(candidate)) return candidate;
		tried += (tried.empty() ? "" : ", ") + candidate;
		if (ns.empty()) break;
	}
	failInput(bags.name(),
		"no CameraInfo topic next to " + image_topic + " (tried " + tried +
			"): give --camera-info-topic TOPIC or --camera-info FILE.yaml");
}

/// The first message of a topic.
template <class M>
boost::shared_ptr<M> firstMessage(const BagSet& bags, const std::string& topic)
{
	boost::shared_ptr<M> msg;
	bags.forEach({topic}, [&](const rosbag::MessageInstance& m) {
		msg = instantiate<M>(m, bags.name());
		return false;
	});
	return msg;
}

std::string frameOfFirst(const BagSet& bags, const std::string& topic)
{
	std::string frame;
	bags.forEach({topic}, [&](const rosbag::MessageInstance& m) {
		if (const auto pc = m.instantiate<sensor_msgs::PointCloud2>()) frame = pc->header.frame_id;
		else if (const auto im = m.instantiate<sensor_msgs::Image>()) frame = im->header.frame_id;
		else if (const auto ci = m.instantiate<sensor_msgs::CompressedImage>()) frame = ci->header.frame_id;
		return false;
	});
	return frame;
}

/// /tf_static, then (only when needed) the /tf pairs that never change.
TransformTree staticTransforms(const BagSet& bags, const std::vector<std::string>& frames, std::string& source)
{
	TransformTree tree;
	const auto readTf = [&](const std::string& topic, const std::function<void(const geometry_msgs::TransformStamped&)>& f) {
		if (!bags.hasTopic(topic)) return;
		bags.forEach({topic}, [&](const rosbag::MessageInstance& m) {
			for (const auto& t : instantiate<tf2_msgs::TFMessage>(m, bags.name())->transforms) f(t);
			return true;
		});
	};
	const auto resolved = [&] {
		for (const auto& f : frames)
			if (!tree.lookup(frames.front(), f)) return false;
		return true;
	};
	readTf("/tf_static", [&](const geometry_msgs::TransformStamped& t) { tree.add(t); });
	source = "/tf_static";
	if (resolved()) return tree;
	StaticTfFilter filter;
	readTf("/tf", [&](const geometry_msgs::TransformStamped& t) { filter.add(t); });
	filter.addStaticTo(tree);
	source = "/tf_static and static /tf";
	return tree;
}

Eigen::Isometry3d toIsometry(const geometry_msgs::Pose& p)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::Quaterniond(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z).normalized().toRotationMatrix();
	T.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
	return T;
}

/// Ground-truth poses of the vehicle frame, relative to the first one, sorted by header stamp.
Trajectory groundTruth(const BagSet& bags, const std::string& topic, const TransformTree& tree,
	const std::string& vehicle_frame, std::vector<std::string>& warnings)
{
	const auto& info = bags.topic(topic, "--gt-topic");
	bags.requireType(info, {"nav_msgs/Odometry", "geometry_msgs/PoseStamped", "geometry_msgs/PointStamped"});
	Trajectory world_T_body;
	std::string body;  // the frame whose pose the messages give, when they say
	bags.forEach({topic}, [&](const rosbag::MessageInstance& m) {
		if (info.type == "nav_msgs/Odometry")
		{
			const auto o = instantiate<nav_msgs::Odometry>(m, bags.name());
			world_T_body.push_back({seconds(o->header.stamp), toIsometry(o->pose.pose)});
			body = o->child_frame_id;
		}
		else if (info.type == "geometry_msgs/PoseStamped")
		{
			const auto p = instantiate<geometry_msgs::PoseStamped>(m, bags.name());
			world_T_body.push_back({seconds(p->header.stamp), toIsometry(p->pose)});
		}
		else  // a position only (an RTK antenna): identity rotation
		{
			const auto p = instantiate<geometry_msgs::PointStamped>(m, bags.name());
			StampedPose s{seconds(p->header.stamp), Eigen::Isometry3d::Identity()};
			s.pose.translation() = Eigen::Vector3d(p->point.x, p->point.y, p->point.z);
			world_T_body.push_back(s);
		}
		return true;
	});
	std::stable_sort(world_T_body.begin(), world_T_body.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
	world_T_body.erase(std::unique(world_T_body.begin(), world_T_body.end(), [](const auto& a, const auto& b) { return a.t == b.t; }),
		world_T_body.end());
	if (world_T_body.empty()) failInput(bags.name(), "--gt-topic " + topic + " has no messages");

	Eigen::Isometry3d body_T_vehicle = Eigen::Isometry3d::Identity();
	const auto T = body.empty() ? std::nullopt : tree.lookup(body, vehicle_frame);
	if (T) body_T_vehicle = *T;
	else
		warnings.push_back(topic + ": " + (body.empty() ? "the messages name no body frame" : "no static transform from '" + body + "'") +
			" to the vehicle frame '" + vehicle_frame + "'; taken as the vehicle frame's own pose" +
			(info.type == "geometry_msgs/PointStamped" ? " (positions only: identity rotation)" : ""));
	for (auto& p : world_T_body) p.pose = p.pose * body_T_vehicle;
	return relativeToFirst(world_T_body);
}

/// Placement of both sensors in the vehicle frame.
struct Placement
{
	Eigen::Isometry3d vehicle_T_lidar = Eigen::Isometry3d::Identity(), vehicle_T_camera = Eigen::Isometry3d::Identity();
	std::string source;
	TransformTree tree;
};

Placement placeSensors(const BagSet& bags, const RosbagImport& opt, const std::string& lidar_frame, const std::string& camera_frame)
{
	Placement p;
	// The frames tf must connect; /tf is read (a pass over the bag's chunks) only when /tf_static does not.
	std::vector<std::string> frames = {lidar_frame};
	if (opt.extrinsics.empty()) frames.push_back(camera_frame);
	if (!opt.vehicle_frame.empty()) frames.push_back(opt.vehicle_frame);
	p.tree = staticTransforms(bags, frames, p.source);
	if (!opt.vehicle_frame.empty())
	{
		const auto v_T_l = p.tree.lookup(opt.vehicle_frame, lidar_frame);
		if (!v_T_l)
			failInput(bags.name(), "--vehicle-frame: no static transform from '" + opt.vehicle_frame + "' to the LiDAR frame '" + lidar_frame + "'");
		p.vehicle_T_lidar = *v_T_l;
	}
	if (!opt.extrinsics.empty())
	{
		p.vehicle_T_camera = p.vehicle_T_lidar * readExtrinsicsFile(opt.extrinsics);
		p.source = opt.extrinsics;
		return p;
	}
	const auto l_T_c = p.tree.lookup(lidar_frame, camera_frame);
	if (!l_T_c)
		failInput(bags.name(),
			"no transform between the LiDAR frame '" + lidar_frame + "' and the camera frame '" + camera_frame +
				"' in /tf_static or unchanging /tf; " + kTfHint);
	p.vehicle_T_camera = p.vehicle_T_lidar * *l_T_c;
	return p;
}

/// Decodes the image and scan messages into single-sensor frames.
class MessageDecoder
{
   public:
	MessageDecoder(const BagSet& bags, const RosbagImport& opt, SensorRig& rig, RosbagImportSummary& summary)
		: bags_(bags), opt_(opt), rig_(rig), summary_(summary)
	{
	}

	/// Sensor 0 = camera, 1 = LiDAR.
	std::pair<int, Frame> decode(const rosbag::MessageInstance& m)
	{
		Frame f;
		f.rig = rig_;
		const std::string where = bags_.name() + ": " + m.getTopic();
		if (m.getTopic() == opt_.lidar_topic)
		{
			const auto pc = instantiate<sensor_msgs::PointCloud2>(m, bags_.name());
			auto scan = decodePointCloud2(*pc, where);
			summary_.dropped_points += scan.dropped;
			f.t = seconds(pc->header.stamp);
			f.scan = std::move(scan.points);
			f.has_scan = true;
			return {1, std::move(f)};
		}
		if (m.getDataType() == kCompressed)
		{
			const auto ci = instantiate<sensor_msgs::CompressedImage>(m, bags_.name());
			f.image = decodeCompressedImage(*ci, where);
			f.t = seconds(ci->header.stamp);
		}
		else
		{
			const auto im = instantiate<sensor_msgs::Image>(m, bags_.name());
			f.image = decodeImage(*im, where);
			f.t = seconds(im->header.stamp);
		}
		auto& cam = rig_.camera;
		if (cam.width == 0 && cam.height == 0)  // CameraInfo without a size: the images give it
		{
			cam.width = static_cast<int>(f.image.getWidth());
			cam.height = static_cast<int>(f.image.getHeight());
			f.rig.camera = cam;
		}
		if (static_cast<int>(f.image.getWidth()) != cam.width || static_cast<int>(f.image.getHeight()) != cam.height)
			failInput(where,
				"image of " + std::to_string(f.image.getWidth()) + "x" +
					std::to_string(f.image.getHeight()) + " but CameraInfo says " +
					std::to_string(cam.width) + "x" + std::to_string(cam.height));
		f.has_image = true;
		return {0, std::move(f)};
	}

   private:
	const BagSet& bags_;
	const RosbagImport& opt_;
	SensorRig& rig_;
	RosbagImportSummary& summary_;
};
}  // namespace

RosbagImportSummary importRosbag(const RosbagImport& opt)
{
	const auto start = SteadyClock::now();
	RosbagImportSummary summary;
	summary.rawlog = opt.out;
	if (!(opt.reorder_window >= 0)) failInput("--reorder-window", "must be a number of seconds >= 0");
	const BagSet bags(opt.bags);
	summary.bag_bytes = bags.bytes();
	bags.requireType(bags.topic(opt.lidar_topic, "--lidar-topic"), {kPointCloud2});
	bags.requireType(bags.topic(opt.image_topic, "--image-topic"), {kImage, kCompressed});
	if (!opt.camera_info_topic.empty() && !opt.camera_info_file.empty())
		failInput("command line", "give --camera-info-topic or --camera-info, not both");

	// Everything that can fail before the first output byte: intrinsics, frames, extrinsics, ground truth.
	boost::shared_ptr<sensor_msgs::CameraInfo> info;
	std::string info_where = opt.camera_info_file;
	if (!opt.camera_info_file.empty())
		info = boost::make_shared<sensor_msgs::CameraInfo>(readCameraInfoFile(opt.camera_info_file));
	else
	{
		const std::string topic = opt.camera_info_topic.empty() ? cameraInfoTopicFor(bags, opt.image_topic) : opt.camera_info_topic;
		bags.requireType(bags.topic(topic, "--camera-info-topic"), {"sensor_msgs/CameraInfo"});
		info = firstMessage<sensor_msgs::CameraInfo>(bags, topic);
		info_where = bags.name() + ": " + topic;
	}
	SensorRig rig;
	rig.has_camera = rig.has_lidar = true;
	rig.camera = fromCameraInfo(*info, opt.image_topic, info_where);
	const std::string lidar_frame = frameOfFirst(bags, opt.lidar_topic);
	std::string camera_frame = frameOfFirst(bags, opt.image_topic);
	if (camera_frame.empty()) camera_frame = info->header.frame_id;
	const Placement place = placeSensors(bags, opt, lidar_frame, camera_frame);
	rig.vehicle_T_lidar = place.vehicle_T_lidar;
	rig.vehicle_T_camera = place.vehicle_T_camera;
	summary.extrinsics_source = place.source;
	Trajectory gt;
	if (!opt.gt_topic.empty())
		gt = groundTruth(bags, opt.gt_topic, place.tree, opt.vehicle_frame.empty() ? lidar_frame : opt.vehicle_frame, summary.warnings);

	io::RawlogWriter writer(opt.out);
	std::size_t counts[2] = {0, 0};
	StampOrder<Frame> order(opt.reorder_window, 2, [&](double, int sensor, Frame&& f) {
		f.index = counts[sensor]++;
		writer.writeFrame(f, opt.camera_label, opt.lidar_label);
	});
	MessageDecoder decoder(bags, opt, rig, summary);
	ProgressLine progress("rosbag", 0);
	std::size_t messages = 0;
	bags.forEach(
		{opt.lidar_topic, opt.image_topic},
		[&](const rosbag::MessageInstance& m) {
			auto [sensor, frame] = decoder.decode(m);
			const double t = frame.t;
			if (!order.push(t, sensor, std::move(frame))) ++summary.late_messages;
			++messages;
			return true;
		},
		[&](double fraction) { progress.update(messages, fraction); });
	order.flush();
	progress.finish();
	summary.images = counts[0];
	summary.scans = counts[1];
	if (summary.images == 0 || summary.scans == 0)
		failInput(bags.name(), "no " + std::string(summary.images == 0 ? "images" : "scans") + " could be read");
	writer.commit();
	if (summary.late_messages > 0)
		summary.warnings.push_back(std::to_string(summary.late_messages) +
			" messages dropped: their stamp repeats one, or is older than --reorder-window allows");
	if (!gt.empty())
	{
		summary.ground_truth = io::groundTruthPathFor(opt.out);
		io::writeTum(summary.ground_truth, gt);
		summary.gt_poses = gt.size();
	}
	summary.seconds = msSince(start) / 1000.0;
	return summary;
}

void listRosbagTopics(const std::vector<std::string>& paths, std::ostream& out)
{
	const BagSet bags(paths);
	std::size_t w_name = 5, w_type = 4;
	for (const auto& t : bags.topics())
	{
		w_name = std::max(w_name, t.name.size());
		w_type = std::max(w_type, t.type.size());
	}
	char line[1024];
	std::snprintf(line, sizeof(line), "%-*s  %-*s  %10s  %9s\n", int(w_name), "topic", int(w_type), "type", "messages", "rate (Hz)");
	out << line;
	for (const auto& t : bags.topics())
	{
		std::snprintf(line, sizeof(line), "%-*s  %-*s  %10zu  %9.2f\n", int(w_name), t.name.c_str(), int(w_type), t.type.c_str(),
			t.messages, t.rateHz());
		out << line;
	}
}
}  // namespace vlo::rosbag_io
