#pragma once
// Test-only: writes vlo frames into a ROS 1 bag the way ROS drivers record them (PointCloud2 with
// Velodyne fields, Image / CompressedImage, CameraInfo, /tf_static, ground truth), with arrival times
// that differ from the header stamps. The tests import such bags and compare with the frames.
#include <vlo/core/frame.h>
#include <vlo/io/trajectory.h>

#include <string>
#include <vector>

namespace vlo::test
{
struct BagLayout
{
	std::string image_encoding = "mono8";  ///< mono8 rgb8 bgr8 rgba8 bgra8 mono16, or "png" / "jpeg" (CompressedImage)
	std::string lidar_topic = "/velodyne_points", image_topic = "/camera/image_raw";
	std::string info_topic = "/camera/camera_info", gt_topic = "/ground_truth";
	std::string gt_type = "nav_msgs/Odometry";  ///< or geometry_msgs/PoseStamped, geometry_msgs/PointStamped
	std::string vehicle_frame = "base_link", lidar_frame = "velodyne", camera_frame = "camera_optical";
	std::string distortion_model;  ///< "" = from the rig camera (plumb_bob / rational_polynomial / equidistant)
	bool tf_static = true;  ///< false: no /tf at all
	bool tf_as_dynamic = false;  ///< the transforms on /tf (repeated each frame, unchanging) instead of /tf_static
	bool big_endian = false;  ///< PointCloud2 data in big-endian byte order
	bool drop_x = false;  ///< broken: the PointCloud2 has no "x" field
	double scan_delay = 0.1, image_delay = 0.02;  ///< arrival (bag time) after the header stamp
	double stamp_offset = 0;  ///< added to every frame time (ROS time 0 means "no time")
};

/// Adds what a VLP-16 driver gives to a simulated VLP-16 scan: ring = the top-down laser id of the point's
/// elevation (+15 deg = 0 ... -15 deg = 15, as Ouster-style drivers number), time = from the azimuth
/// (-0.05 .. 0.05 s around the stamp).
void addVlp16Fields(PointCloud& scan);

/// Writes the frames (each may have an image and a scan, at frame.t) and the ground truth (vehicle poses).
void writeBag(const std::string& path, const std::vector<Frame>& frames, const Trajectory& gt, const BagLayout& layout);
}  // namespace vlo::test
