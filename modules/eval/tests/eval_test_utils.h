#pragma once
// Trajectory builders shared by the eval tests.
#include <vlo/io/trajectory.h>

#include <Eigen/Geometry>
#include <cmath>

namespace vlo::test
{
inline Eigen::Isometry3d makePose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = R;
	T.translation() = t;
	return T;
}

inline Eigen::Matrix3d Rz(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

/// P_0 = I, P_i = P_{i-1} * step; stamps i * dt.
inline Trajectory fromSteps(std::size_t n, const Eigen::Isometry3d& step, double dt = 0.1)
{
	Trajectory tr(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		tr[i].t = i * dt;
		if (i > 0) tr[i].pose = tr[i - 1].pose * step;
	}
	return tr;
}

/// A planar step turning by dtheta whose chord (distance between consecutive positions) is c:
/// composed n times it traces a circle of radius c / (2 sin(dtheta/2)) (a line for dtheta = 0).
inline Eigen::Isometry3d arcStep(double c, double dtheta)
{
	return makePose(Rz(dtheta), c * Eigen::Vector3d(std::cos(dtheta / 2), std::sin(dtheta / 2), 0));
}

/// Positions scaled about the origin by s, orientations kept: a constant scale error.
inline Trajectory scaled(Trajectory tr, double s)
{
	for (auto& p : tr) p.pose.translation() *= s;
	return tr;
}

/// A smooth 3D trajectory with rotation about every axis, for tests that need non-degenerate data.
inline Trajectory wiggly(std::size_t n, double dt = 0.1)
{
	Trajectory tr(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		const double t = i * dt;
		tr[i].t = t;
		const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.3 * std::sin(0.5 * t), Eigen::Vector3d::UnitX()) *
			Eigen::AngleAxisd(0.2 * std::cos(0.3 * t), Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(0.1 * t, Eigen::Vector3d::UnitZ()))
									  .toRotationMatrix();
		tr[i].pose = makePose(R, Eigen::Vector3d(10 * std::cos(0.1 * t), 10 * std::sin(0.1 * t), std::sin(0.7 * t)) * 1.0);
	}
	return tr;
}
}  // namespace vlo::test
