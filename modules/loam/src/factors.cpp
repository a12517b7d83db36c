#include "vlo/loam/factors.h"

namespace vlo::loam
{
namespace
{
Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d m;
	m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return m;
}
}  // namespace

Eigen::Matrix<double, 3, 4> rotatedPointJacobian(const double* q, const Eigen::Vector3d& p)
{
	const Eigen::Vector3d v(q[0], q[1], q[2]);
	const double w = q[3];
	Eigen::Matrix<double, 3, 4> J;
	// d/dv [2w (v x p)] = -2w [p]x ;  d/dv [2 v x (v x p)] = 2((v.p) I + v p^T - 2 p v^T)
	J.leftCols<3>() = -2.0 * w * skew(p) +
		2.0 * (v.dot(p) * Eigen::Matrix3d::Identity() + v * p.transpose() - 2.0 * p * v.transpose());
	J.col(3) = 2.0 * v.cross(p);
	return J;
}

EdgeFactor::EdgeFactor(const EdgeMatch& m)
	: p_(m.p), a_(m.a), P_(Eigen::Matrix3d::Identity() - m.u * m.u.transpose())
{
}

bool EdgeFactor::Evaluate(double const* const* x, double* residuals, double** jacobians) const
{
	const Eigen::Map<const Eigen::Quaterniond> q(x[0]);
	const Eigen::Map<const Eigen::Vector3d> t(x[1]);
	Eigen::Map<Eigen::Vector3d> r(residuals);
	r = P_ * (q * p_ + t - a_);
	if (jacobians)
	{
		using J34 = Eigen::Matrix<double, 3, 4, Eigen::RowMajor>;
		using J33 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
		if (jacobians[0])
		{
			Eigen::Map<J34> Jq(jacobians[0]);
			Jq = P_ * rotatedPointJacobian(x[0], p_);
		}
		if (jacobians[1])
		{
			Eigen::Map<J33> Jt(jacobians[1]);
			Jt = P_;
		}
	}
	return true;
}

bool PlaneFactor::Evaluate(double const* const* x, double* residuals, double** jacobians) const
{
	const Eigen::Map<const Eigen::Quaterniond> q(x[0]);
	const Eigen::Map<const Eigen::Vector3d> t(x[1]);
	residuals[0] = m_.n.dot(q * m_.p + t) + m_.d;
	if (jacobians)
	{
		if (jacobians[0])
		{
			Eigen::Map<Eigen::Matrix<double, 1, 4>> Jq(jacobians[0]);
			Jq = m_.n.transpose() * rotatedPointJacobian(x[0], m_.p);
		}
		if (jacobians[1])
		{
			Eigen::Map<Eigen::Matrix<double, 1, 3>> Jt(jacobians[1]);
			Jt = m_.n.transpose();
		}
	}
	return true;
}
}  // namespace vlo::loam
