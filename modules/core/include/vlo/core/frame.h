#pragma once
// What the estimators consume: one synchronized camera + LiDAR frame and the sensor rig.
#include <mrpt/img/CImage.h>
#include <mrpt/img/DistortionModel.h>

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vlo
{
/// A LiDAR return in the LiDAR sensor frame (metres), with what the sensor told of it (24 bytes).
struct LidarPoint
{
	float x = 0, y = 0, z = 0, intensity = 0;
	/// Capture time in seconds relative to the frame's time (Frame::t), when the scan has_time.
	float time = 0;
	/// Beam (laser) index ordered by elevation, 0 = lowest, when the scan has_ring.
	std::uint16_t ring = 0;
};

/// The points of one sweep, and which of the optional per-point fields hold the sensor's values.
struct PointCloud : std::vector<LidarPoint>
{
	using std::vector<LidarPoint>::vector;
	bool has_time = false, has_ring = false;
	/// The times were derived from the azimuth ([lidar] point_times), not written by the sensor.
	bool time_from_azimuth = false;
};

/// Intrinsics of an image and its lens distortion, in MRPT's TCamera convention.
struct PinholeCamera
{
	double fx = 0, fy = 0, cx = 0, cy = 0;
	int width = 0, height = 0;
	/// none; plumb_bob: dist = [k1 k2 p1 p2 k3 k4 k5 k6] (OpenCV's rational model when k4..k6 are not 0);
	/// kannala_brandt (ROS "equidistant", OpenCV fisheye): dist = [k1 k2 0 0 k3 k4].
	mrpt::img::DistortionModel distortion = mrpt::img::DistortionModel::none;
	std::array<double, 8> dist{};

	Eigen::Matrix3d K() const;
	bool valid() const { return fx > 0 && fy > 0 && width > 0 && height > 0; }
	/// True when the image is not an ideal pinhole image (a model with a non-zero coefficient).
	bool distorted() const;
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
