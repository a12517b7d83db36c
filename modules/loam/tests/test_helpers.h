#pragma once
// Shared helpers of the LOAM tests: option presets and pose error measures.
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

inline double translationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return (a.translation() - b.translation()).norm();
}

inline double rotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return rotationAngle(a.linear().transpose() * b.linear()) * 180.0 / M_PI;
}
}  // namespace vlo::loam::test
