#include <vlo/core/error.h>
#include <vlo/eval/umeyama.h>

#include <Eigen/SVD>
#include <stdexcept>

namespace vlo::eval
{
Sim3 umeyama(const std::vector<Eigen::Vector3d>& src, const std::vector<Eigen::Vector3d>& dst, bool with_scale)
{
	if (src.size() != dst.size() || src.empty())
		throw std::invalid_argument("umeyama: point sets must be non-empty and of equal size");
	const double n = static_cast<double>(src.size());
	Eigen::Vector3d mu_s = Eigen::Vector3d::Zero(), mu_d = Eigen::Vector3d::Zero();
	for (std::size_t i = 0; i < src.size(); ++i)
	{
		mu_s += src[i];
		mu_d += dst[i];
	}
	mu_s /= n;
	mu_d /= n;
	double var_s = 0;
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();  // (1/n) sum (d - mu_d)(s - mu_s)^T
	for (std::size_t i = 0; i < src.size(); ++i)
	{
		const Eigen::Vector3d a = src[i] - mu_s, b = dst[i] - mu_d;
		var_s += a.squaredNorm();
		cov += b * a.transpose();
	}
	var_s /= n;
	cov /= n;

	Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
	const Eigen::Vector3d D = svd.singularValues();
	Eigen::Vector3d S = Eigen::Vector3d::Ones();
	if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) S(2) = -1;

	Sim3 T;
	const double tiny = 1e-9 * D(0);
	if (D(0) <= 1e-300)
		T.R.setIdentity();  // every point coincides: no rotation information at all
	else if (D(1) <= tiny)
		// Rank 1 (collinear): any rotation taking the source line onto the target line is optimal;
		// the SVD would pick an arbitrary roll about it, so take the smallest rotation instead.
		T.R = Eigen::Quaterniond::FromTwoVectors(svd.matrixV().col(0), svd.matrixU().col(0)).toRotationMatrix();
	else
		T.R = svd.matrixU() * S.asDiagonal() * svd.matrixV().transpose();

	if (with_scale)
	{
		if (var_s <= 1e-18) failInput("alignment", "estimated positions do not spread; the Sim(3) scale is undefined");
		// Rank 1 handled above: trace(D S) reduces to D(0) because the other values vanish.
		T.s = (D.array() * S.array()).sum() / var_s;
	}
	T.t = mu_d - T.s * T.R * mu_s;
	return T;
}
}  // namespace vlo::eval
