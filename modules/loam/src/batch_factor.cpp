#include <ceres/loss_function.h>
#include <vlo/loam/factors.h>

#include <cmath>

namespace vlo::loam
{
BatchFactor::BatchFactor(
	const EdgeMatch* edges, int n_edges, const PlaneMatch* planes, int n_planes, const ceres::LossFunction* loss)
	: edges_(edges), planes_(planes), n_edges_(n_edges), n_planes_(n_planes), loss_(loss)
{
	set_num_residuals(3 * n_edges + n_planes);
	mutable_parameter_block_sizes()->assign({4, 3});
}

namespace
{
// For r~ = w(s) r with w = sqrt(rho(s)/s), s = |r|^2:  dr~ = (w I + 2 w'(s) r r^T) dr.
struct Robust
{
	double w = 1, g = 0;  ///< residual scale and 2 w'(s)
};
Robust robustify(const ceres::LossFunction* loss, double s)
{
	Robust k;
	if (!loss || s < 1e-20) return k;  // rho(s) ~ s near 0 for every Ceres loss
	double rho[3];
	loss->Evaluate(s, rho);
	k.w = std::sqrt(rho[0] / s);
	k.g = (rho[1] * s - rho[0]) / (s * s * k.w);
	return k;
}
}  // namespace

bool BatchFactor::Evaluate(double const* const* x, double* residuals, double** jacobians) const
{
	const Eigen::Map<const Eigen::Quaterniond> q(x[0]);
	const Eigen::Map<const Eigen::Vector3d> t(x[1]);
	double* Jq = jacobians ? jacobians[0] : nullptr;
	double* Jt = jacobians ? jacobians[1] : nullptr;
	int row = 0;
	for (int i = 0; i < n_edges_; ++i, row += 3)
	{
		const EdgeMatch& e = edges_[i];
		const Eigen::Vector3d d = q * e.p + t - e.a;
		const Eigen::Vector3d r = d - e.u * e.u.dot(d);
		const Robust k = robustify(loss_, r.squaredNorm());
		Eigen::Map<Eigen::Vector3d>(residuals + row) = k.w * r;
		if (!Jq && !Jt) continue;
		// (w I + g r r^T)(I - u u^T): residual scaling times the line projector.
		const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - e.u * e.u.transpose();
		const Eigen::Matrix3d A = (k.w * Eigen::Matrix3d::Identity() + k.g * r * r.transpose()) * P;
		if (Jq)
		{
			Eigen::Map<Eigen::Matrix<double, 3, 4, Eigen::RowMajor>> J(Jq + 4 * row);
			J = A * rotatedPointJacobian(x[0], e.p);
		}
		if (Jt)
		{
			Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> J(Jt + 3 * row);
			J = A;
		}
	}
	for (int i = 0; i < n_planes_; ++i, ++row)
	{
		const PlaneMatch& p = planes_[i];
		const double r = p.n.dot(q * p.p + t) + p.d;
		const Robust k = robustify(loss_, r * r);
		residuals[row] = k.w * r;
		const double a = k.w + k.g * r * r;
		if (Jq)
		{
			Eigen::Map<Eigen::Matrix<double, 1, 4>> J(Jq + 4 * row);
			J = a * p.n.transpose() * rotatedPointJacobian(x[0], p.p);
		}
		if (Jt)
		{
			Eigen::Map<Eigen::Matrix<double, 1, 3>> J(Jt + 3 * row);
			J = a * p.n.transpose();
		}
	}
	return true;
}
}  // namespace vlo::loam
