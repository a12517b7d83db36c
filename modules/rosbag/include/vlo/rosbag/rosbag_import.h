#pragma once
// vlo-import rosbag: ROS 1 bags (PointCloud2 + Image/CompressedImage + CameraInfo, tf) -> vlo rawlog.
// The vehicle frame is the LiDAR frame unless vehicle_frame names a tf frame. See doc/ROSBAG.md.
#include <iosfwd>
#include <string>
#include <vector>

namespace vlo::rosbag_io
{
struct RosbagImport
{
	std::vector<std::string> bags;
	std::string lidar_topic, image_topic;
	std::string camera_info_topic;  ///< "" = the camera_info topic next to the image topic
	std::string camera_info_file;  ///< camera calibration YAML instead of a topic (bags without CameraInfo)
	std::string extrinsics;  ///< FILE.yaml; "" = from /tf_static (and static /tf)
	std::string gt_topic;  ///< "" = no ground truth
	std::string vehicle_frame;  ///< "" = the LiDAR frame
	std::string out;
	double reorder_window = 1.0;  ///< seconds of stamps held to put messages in stamp order
	std::string camera_label = "CAMERA", lidar_label = "LIDAR";
};

struct RosbagImportSummary
{
	std::string rawlog, ground_truth;  ///< written files (ground_truth empty when none)
	std::size_t images = 0, scans = 0, gt_poses = 0;
	std::size_t dropped_points = 0;  ///< non-finite points
	std::size_t late_messages = 0;  ///< dropped: older than the reorder window allows, or a repeated stamp
	std::size_t bag_bytes = 0;
	std::string extrinsics_source;  ///< "/tf_static", "/tf", or the file
	std::vector<std::string> warnings;
	double seconds = 0;
};

/// Throws InputError (naming the bag, topic or option) for anything it cannot convert; writes nothing then.
RosbagImportSummary importRosbag(const RosbagImport& opt);

/// Prints the topics of the bags as a table: topic, type, messages, rate (Hz).
void listRosbagTopics(const std::vector<std::string>& bags, std::ostream& out);
}  // namespace vlo::rosbag_io
