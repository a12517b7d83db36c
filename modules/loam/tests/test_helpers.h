#pragma once
// Shared helpers of the LOAM tests: option presets, planar poses and pose error measures.
#include <vlo/core/se3.h>
#include <vlo/loam/options.h>

#include <Eigen/Geometry>
#include <cmath>

namespace vlo::loam::test
{
inline LoamOptions hdl64Options()
{
	LoamOptions o;
	o.scan.ring_model = "hdl64";
	return o;
}

inline LoamOptions vlp16Options()
{
	LoamOptions o;
	o.scan.ring_model = "uniform";
	o.scan.n_rings = 16;
	o.scan.vfov_min_deg = -15;
	o.scan.vfov_max_deg = 15;
	o.mapping.edge_leaf = 0.3;
	o.mapping.plane_leaf = 0.6;
	return o;
}

/// x, y [m] and a turn of yaw_deg about z: a motion on flat ground.
inline Eigen::Isometry3d planarPose(double x, double y, double yaw_deg)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	T.translation() = Eigen::Vector3d(x, y, 0);
	return T;
}

inline double translationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return (a.translation() - b.translation()).norm();
}

inline double rotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return rotationAngle(a.linear().transpose() * b.linear()) * 180.0 / M_PI;
}
}  // namespace vlo::loam::test
