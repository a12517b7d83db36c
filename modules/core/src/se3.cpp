#include <vlo/core/se3.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace vlo
{
Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& p)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.matrix() = p.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
	return T;
}

mrpt::poses::CPose3D toCPose3D(const Eigen::Isometry3d& T)
{
	mrpt::math::CMatrixDouble44 M;
	M.asEigen() = T.matrix();
	return mrpt::poses::CPose3D(M);
}

Sim3 Sim3::inverse() const
{
	Sim3 inv;
	inv.s = 1.0 / s;
	inv.R = R.transpose();
	inv.t = -inv.s * (inv.R * t);
	return inv;
}

Sim3 Sim3::operator*(const Sim3& o) const
{
	Sim3 r;
	r.s = s * o.s;
	r.R = R * o.R;
	r.t = s * (R * o.t) + t;
	return r;
}

double rotationAngle(const Eigen::Matrix3d& R)
{
	// atan2 form stays accurate for tiny angles, unlike acos((tr-1)/2).
	const Eigen::Vector3d axis(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
	return std::atan2(0.5 * axis.norm(), 0.5 * (R.trace() - 1.0));
}

Eigen::Isometry3d interpolate(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B, double a)
{
	const Eigen::Quaterniond qa(A.rotation()), qb(B.rotation());
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = qa.slerp(a, qb).toRotationMatrix();
	T.translation() = (1 - a) * A.translation() + a * B.translation();
	return T;
}

Eigen::Matrix3d orthonormalize(const Eigen::Matrix3d& M)
{
	Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
	Eigen::Matrix3d R = svd.matrixU() * svd.matrixV().transpose();
	if (R.determinant() < 0)
	{
		Eigen::Matrix3d U = svd.matrixU();
		U.col(2) *= -1;
		R = U * svd.matrixV().transpose();
	}
	return R;
}
}  // namespace vlo
