#include <vlo/scale/triangulation.h>

#include <algorithm>
#include <cmath>

namespace vlo::scale
{
namespace
{
constexpr double kDegPerRad = 57.295779513082320876;
}

Triangulated triangulateMidpoint(const Eigen::Matrix3d& Kinv, const Eigen::Isometry3d& cur_T_prev,
	cv::Point2f x_prev, cv::Point2f x_cur, double min_parallax_deg)
{
	Triangulated out;
	// Both rays in the C(i-1) frame: a from the origin, b from the centre c of C(i).
	const Eigen::Matrix3d Rt = cur_T_prev.linear().transpose();
	const Eigen::Vector3d c = -Rt * cur_T_prev.translation();
	const Eigen::Vector3d a = Kinv * Eigen::Vector3d(x_prev.x, x_prev.y, 1.0);
	const Eigen::Vector3d b = Rt * (Kinv * Eigen::Vector3d(x_cur.x, x_cur.y, 1.0));

	const double cosAng = std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0);
	out.parallax_deg = std::acos(cosAng) * kDegPerRad;
	if (c.squaredNorm() == 0 || out.parallax_deg < min_parallax_deg || out.parallax_deg == 0) return out;

	// Least squares l0 a - l1 b = c (normal equations of the 2x2 system).
	const double aa = a.dot(a), ab = a.dot(b), bb = b.dot(b), ac = a.dot(c), bc = b.dot(c);
	const double det = aa * bb - ab * ab;
	if (!(det > 0)) return out;
	const double l0 = (ac * bb - ab * bc) / det;
	const double l1 = (ab * ac - aa * bc) / det;
	out.X = 0.5 * (l0 * a + c + l1 * b);
	out.depth = out.X.z();
	out.status = (l0 > 0 && l1 > 0 && out.depth > 0) ? TriangulationStatus::Ok : TriangulationStatus::Behind;
	return out;
}
}  // namespace vlo::scale
