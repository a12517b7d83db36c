#include <vlo/vo/triangulation.h>

#include <Eigen/SVD>
#include <cmath>

namespace vlo::vo
{
bool triangulate(const SE3& T1w, const SE3& T2w, const Vec3& m1, const Vec3& m2, Vec3& Xw)
{
	const Eigen::Matrix<double, 3, 4> P1 = T1w.matrix().topRows<3>(), P2 = T2w.matrix().topRows<3>();
	Eigen::Matrix4d A;
	A.row(0) = m1.x() * P1.row(2) - P1.row(0);
	A.row(1) = m1.y() * P1.row(2) - P1.row(1);
	A.row(2) = m2.x() * P2.row(2) - P2.row(0);
	A.row(3) = m2.y() * P2.row(2) - P2.row(1);
	const Eigen::JacobiSVD<Eigen::Matrix4d> svd(A, Eigen::ComputeFullV);
	const Eigen::Vector4d h = svd.matrixV().col(3);
	if (std::abs(h(3)) < 1e-12) return false;
	Xw = h.head<3>() / h(3);
	return Xw.allFinite();
}
}  // namespace vlo::vo
