#include <vlo/loam/factors.h>

#include <cmath>

namespace vlo::loam
{
BatchFactor::BatchFactor(const EdgeMatch* edges, const double* edge_weights, int n_edges, const PlaneMatch* planes,
	const double* plane_weights, int n_planes)
	: edges_(edges), planes_(planes), edge_w_(edge_weights), plane_w_(plane_weights), n_edges_(n_edges), n_planes_(n_planes)
{
	set_num_residuals(3 * n_edges + n_planes);
	mutable_parameter_block_sizes()->assign({4, 3});
}

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
		const double w = edge_w_ ? std::sqrt(edge_w_[i]) : 1.0;
		// w (I - u u^T): the weighted line projector.
		const Eigen::Matrix3d A = w * (Eigen::Matrix3d::Identity() - e.u * e.u.transpose());
		Eigen::Map<Eigen::Vector3d>(residuals + row) = A * (q * e.p + t - e.a);
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
		const double w = plane_w_ ? std::sqrt(plane_w_[i]) : 1.0;
		residuals[row] = w * (p.n.dot(q * p.p + t) + p.d);
		if (Jq)
		{
			Eigen::Map<Eigen::Matrix<double, 1, 4>> J(Jq + 4 * row);
			J = w * p.n.transpose() * rotatedPointJacobian(x[0], p.p);
		}
		if (Jt)
		{
			Eigen::Map<Eigen::Matrix<double, 1, 3>> J(Jt + 3 * row);
			J = w * p.n.transpose();
		}
	}
	return true;
}
}  // namespace vlo::loam
