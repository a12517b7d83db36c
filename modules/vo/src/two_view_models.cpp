// Homography and fundamental matrix from correspondences, and their ORB-SLAM scores.
#include <vlo/vo/two_view.h>

#include <Eigen/SVD>
#include <cmath>

namespace vlo::vo::detail
{
namespace
{
/// Hartley normalisation (ORB-SLAM's variant): zero mean, unit mean absolute deviation per axis.
Mat3 normalize(const std::vector<Vec2>& x, std::vector<Vec2>& out)
{
	Vec2 mean = Vec2::Zero();
	for (const auto& p : x) mean += p;
	mean /= static_cast<double>(x.size());
	Vec2 dev = Vec2::Zero();
	for (const auto& p : x) dev += (p - mean).cwiseAbs();
	dev /= static_cast<double>(x.size());
	const double sx = dev.x() > 0 ? 1.0 / dev.x() : 1.0, sy = dev.y() > 0 ? 1.0 / dev.y() : 1.0;
	out.resize(x.size());
	for (std::size_t i = 0; i < x.size(); ++i) out[i] = Vec2((x[i].x() - mean.x()) * sx, (x[i].y() - mean.y()) * sy);
	Mat3 T;
	T << sx, 0, -mean.x() * sx, 0, sy, -mean.y() * sy, 0, 0, 1;
	return T;
}

Mat3 nullVector(const Eigen::MatrixXd& A)
{
	const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
	const Eigen::VectorXd v = svd.matrixV().col(8);
	Mat3 M;
	M << v(0), v(1), v(2), v(3), v(4), v(5), v(6), v(7), v(8);
	return M;
}
}  // namespace

Mat3 homographyDLT(const std::vector<Vec2>& x1, const std::vector<Vec2>& x2)
{
	std::vector<Vec2> n1, n2;
	const Mat3 T1 = normalize(x1, n1), T2 = normalize(x2, n2);
	Eigen::MatrixXd A(2 * n1.size(), 9);
	for (std::size_t i = 0; i < n1.size(); ++i)
	{
		const double u1 = n1[i].x(), v1 = n1[i].y(), u2 = n2[i].x(), v2 = n2[i].y();
		A.row(2 * i) << 0, 0, 0, -u1, -v1, -1, v2 * u1, v2 * v1, v2;
		A.row(2 * i + 1) << u1, v1, 1, 0, 0, 0, -u2 * u1, -u2 * v1, -u2;
	}
	return T2.inverse() * nullVector(A) * T1;
}

Mat3 fundamental8(const std::vector<Vec2>& x1, const std::vector<Vec2>& x2)
{
	std::vector<Vec2> n1, n2;
	const Mat3 T1 = normalize(x1, n1), T2 = normalize(x2, n2);
	Eigen::MatrixXd A(n1.size(), 9);
	for (std::size_t i = 0; i < n1.size(); ++i)
	{
		const double u1 = n1[i].x(), v1 = n1[i].y(), u2 = n2[i].x(), v2 = n2[i].y();
		A.row(i) << u2 * u1, u2 * v1, u2, v2 * u1, v2 * v1, v2, u1, v1, 1;
	}
	const Mat3 Fn = nullVector(A);
	Eigen::JacobiSVD<Mat3> svd(Fn, Eigen::ComputeFullU | Eigen::ComputeFullV);
	Vec3 s = svd.singularValues();
	s(2) = 0;  // rank 2
	const Mat3 F = svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();
	return T2.transpose() * F * T1;
}

double scoreHomography(const Mat3& H21, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2, double sigma,
	std::vector<char>& inliers)
{
	constexpr double th = 5.991;  // chi2, 2 dof, 95%
	const double inv_s2 = 1.0 / (sigma * sigma);
	const Mat3 H12 = H21.inverse();
	inliers.assign(x1.size(), 0);
	double score = 0;
	for (std::size_t i = 0; i < x1.size(); ++i)
	{
		const Vec2 a = (H21 * x1[i].homogeneous()).hnormalized(), b = (H12 * x2[i].homogeneous()).hnormalized();
		const double c2 = (a - x2[i]).squaredNorm() * inv_s2, c1 = (b - x1[i]).squaredNorm() * inv_s2;
		if (!(c1 <= th) || !(c2 <= th)) continue;  // also rejects NaN
		score += (th - c1) + (th - c2);
		inliers[i] = 1;
	}
	return score;
}

double scoreFundamental(const Mat3& F21, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2, double sigma,
	std::vector<char>& inliers)
{
	constexpr double th = 3.841, th_score = 5.991;  // chi2 1 dof for the test, 2 dof for the score (as H)
	const double inv_s2 = 1.0 / (sigma * sigma);
	inliers.assign(x1.size(), 0);
	double score = 0;
	for (std::size_t i = 0; i < x1.size(); ++i)
	{
		const Vec3 l2 = F21 * x1[i].homogeneous(), l1 = F21.transpose() * x2[i].homogeneous();
		const double d2 = l2.dot(x2[i].homogeneous()), d1 = l1.dot(x1[i].homogeneous());
		const double c2 = d2 * d2 / l2.head<2>().squaredNorm() * inv_s2, c1 = d1 * d1 / l1.head<2>().squaredNorm() * inv_s2;
		if (!(c1 <= th) || !(c2 <= th)) continue;
		score += (th_score - c1) + (th_score - c2);
		inliers[i] = 1;
	}
	return score;
}
}  // namespace vlo::vo::detail
