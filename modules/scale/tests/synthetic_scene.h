#pragma once
// A textured street of planes (ground, two facades, an end wall, a few panels) seen by a KITTI-like
// camera (1241x376, f = 718) and a spinning LiDAR ray cast against the same planes. Images are ray
// cast per pixel with trilinear mip-mapped textures, so that a surface looks the same from both
// poses and Lucas-Kanade tracks it as it would track a real one.
#include <vlo/core/frame.h>

#include <opencv2/core/mat.hpp>

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace vlo::scale::test
{
struct TexturedPlane
{
	Eigen::Vector3d origin, u, v;  ///< corner and unit axes (world frame)
	double width = 0, height = 0;  ///< extent along u and v [m]
	int texture = 0;
	double texel = 0.03;  ///< [m] of one texel at mip level 0
};

struct Scene
{
	std::vector<TexturedPlane> planes;
	std::vector<std::vector<cv::Mat>> mips;  ///< per texture: float images, level 0 first

	/// Nearest hit of the ray o + t dir (t > 0): distance t and plane index, or false.
	bool intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& dir, double& t, int& plane) const;
	/// Grey level at world point X on `plane` for a footprint of `footprint` metres per pixel.
	float shade(int plane, const Eigen::Vector3d& X, double footprint) const;
};

/// The street, with random textures from `seed`.
Scene streetScene(std::uint32_t seed);

struct LidarModel
{
	std::vector<double> elevations_deg;
	double azimuth_step_deg = 0.2;
	double range_noise = 0;  ///< [m] Gaussian sigma
	double max_range = 120;
};
LidarModel hdl64();
LidarModel vlp16();

/// KITTI-like rig: LiDAR 1.73 m above the ground at the vehicle origin, camera 0.27 m ahead of it.
SensorRig kittiRig();

/// 8-bit grey image seen from `world_T_camera` (optical frame), with Gaussian pixel noise.
cv::Mat renderImage(const Scene& scene, const PinholeCamera& cam, const Eigen::Isometry3d& world_T_camera,
	double noise_sigma = 0, std::uint32_t seed = 0);

/// One sweep (no motion distortion), points in the LiDAR frame.
PointCloud scanScene(const Scene& scene, const LidarModel& m, const Eigen::Isometry3d& world_T_lidar,
	std::uint32_t seed = 0);

/// Two consecutive frames of the rig driving down the street.
struct FramePair
{
	SensorRig rig;
	cv::Mat prev, cur;  ///< C(i-1), C(i)
	PointCloud scan;  ///< L(i-1)
	Eigen::Isometry3d cur_T_prev;  ///< true T_{C(i-1)}^{C(i)} (metres)
};
/// Vehicle motion between the frames: `forward` metres and `yaw_deg` (plus a small lateral drift).
FramePair makePair(const Scene& scene, const LidarModel& lidar, double forward = 1.0, double yaw_deg = 1.5,
	double image_noise = 1.0, std::uint32_t seed = 7);

/// The relative pose with its translation multiplied by k: a monocular VO with a wrong scale.
Eigen::Isometry3d withScaledTranslation(const Eigen::Isometry3d& T, double k);
}  // namespace vlo::scale::test
