#pragma once
// What the estimators consume: one synchronized camera + LiDAR frame and the sensor rig.
#include <mrpt/img/CImage.h>

#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

namespace vlo
{
/// A LiDAR return in the LiDAR sensor frame (metres).
struct LidarPoint
{
	float x = 0, y = 0, z = 0, intensity = 0;
};
using PointCloud = std::vector<LidarPoint>;

/// Pinhole intrinsics of a rectified image (no distortion).
struct PinholeCamera
{
	double fx = 0, fy = 0, cx = 0, cy = 0;
	int width = 0, height = 0;

	Eigen::Matrix3d K() const;
	bool valid() const { return fx > 0 && fy > 0 && width > 0 && height > 0; }
};

/// Sensor placement on the vehicle (x forward, y left, z up). The camera pose is that of its
/// optical frame (z forward, x right, y down).
struct SensorRig
{
	bool has_camera = false, has_lidar = false;
	PinholeCamera camera;
	Eigen::Isometry3d vehicle_T_camera = Eigen::Isometry3d::Identity();
	Eigen::Isometry3d vehicle_T_lidar = Eigen::Isometry3d::Identity();

	/// Maps LiDAR-frame points into the camera optical frame.
	Eigen::Isometry3d camera_T_lidar() const { return vehicle_T_camera.inverse() * vehicle_T_lidar; }
};

/// One synchronized frame. `t` is the dataset's own time in seconds.
struct Frame
{
	std::size_t index = 0;
	double t = 0;
	bool has_image = false, has_scan = false;
	mrpt::img::CImage image;  ///< grayscale, rectified
	PointCloud scan;  ///< LiDAR frame
	SensorRig rig;
};
}  // namespace vlo
