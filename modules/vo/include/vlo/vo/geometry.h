#pragma once
// Small geometric helpers shared by the VO: pinhole projection, epipolar geometry, pose building.
// Poses are Tcw (world -> camera) as in ORB-SLAM; the camera is rectified (no distortion).
#include <vlo/core/frame.h>

#include <Eigen/Geometry>

namespace vlo::vo
{
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using SE3 = Eigen::Isometry3d;

inline Vec2 project(const PinholeCamera& c, const Vec3& Xc)
{
	const double iz = 1.0 / Xc.z();
	return {c.fx * Xc.x() * iz + c.cx, c.fy * Xc.y() * iz + c.cy};
}

/// Ray through pixel x at depth 1.
inline Vec3 unproject(const PinholeCamera& c, const Vec2& x)
{
	return {(x.x() - c.cx) / c.fx, (x.y() - c.cy) / c.fy, 1.0};
}

inline bool inImage(const PinholeCamera& c, const Vec2& x, double margin = 0)
{
	return x.x() >= margin && x.y() >= margin && x.x() < c.width - margin && x.y() < c.height - margin;
}

Mat3 skew(const Vec3& v);
SE3 makeSE3(const Mat3& R, const Vec3& t);
/// Camera centre in the world of a pose Tcw.
inline Vec3 centre(const SE3& Tcw) { return -(Tcw.linear().transpose() * Tcw.translation()); }

/// F12 such that x1^T F12 x2 = 0 for cameras with poses T1w and T2w (pixels, homogeneous).
Mat3 fundamentalBetween(const SE3& T1w, const SE3& T2w, const PinholeCamera& c);
}  // namespace vlo::vo
