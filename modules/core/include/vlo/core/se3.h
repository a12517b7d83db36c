#pragma once
// Bridges between Eigen rigid/similarity transforms and mrpt::poses.
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>

namespace vlo
{
Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& p);
mrpt::poses::CPose3D toCPose3D(const Eigen::Isometry3d& T);

/// Similarity transform x -> s * R * x + t.
struct Sim3
{
	double s = 1.0;
	Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
	Eigen::Vector3d t = Eigen::Vector3d::Zero();

	Eigen::Vector3d operator*(const Eigen::Vector3d& x) const { return s * R * x + t; }
	Sim3 inverse() const;
	Sim3 operator*(const Sim3& o) const;
};

/// Rotation angle of R in radians, robust near 0 and pi.
double rotationAngle(const Eigen::Matrix3d& R);

/// Interpolates between two poses: translation linearly, rotation by slerp; a in [0, 1].
Eigen::Isometry3d interpolate(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B, double a);

/// Closest rotation to M (SVD projection onto SO(3)).
Eigen::Matrix3d orthonormalize(const Eigen::Matrix3d& M);
}  // namespace vlo
