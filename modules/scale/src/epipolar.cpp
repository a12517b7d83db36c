#include <vlo/scale/epipolar.h>

#include <cmath>
#include <limits>

namespace vlo::scale
{
Eigen::Matrix3d fundamentalMatrix(const Eigen::Matrix3d& K, const Eigen::Isometry3d& cur_T_prev)
{
	const Eigen::Vector3d t = cur_T_prev.translation();
	const double n = t.norm();
	if (!(n > 0)) return Eigen::Matrix3d::Zero();
	const Eigen::Vector3d u = t / n;
	Eigen::Matrix3d tx;
	tx << 0, -u.z(), u.y(), u.z(), 0, -u.x(), -u.y(), u.x(), 0;
	const Eigen::Matrix3d Kinv = K.inverse();
	return Kinv.transpose() * tx * cur_T_prev.linear() * Kinv;
}

Eigen::Vector3d epipolarLine(const Eigen::Matrix3d& F, cv::Point2f x_prev)
{
	return F * Eigen::Vector3d(x_prev.x, x_prev.y, 1.0);
}

double normalError(const Eigen::Vector3d& l, cv::Point2f x)
{
	const double n = std::hypot(l.x(), l.y());
	if (!(n > 0)) return std::numeric_limits<double>::infinity();
	return std::abs(l.x() * x.x + l.y() * x.y + l.z()) / n;
}

double absCosToLine(const Eigen::Vector3d& l, cv::Point2f g)
{
	const double n = std::hypot(l.x(), l.y()) * std::hypot(g.x, g.y);
	if (!(n > 0)) return 0;
	return std::abs(-l.y() * g.x + l.x() * g.y) / n;
}

CullResult cullMatch(
	const Eigen::Matrix3d& F, cv::Point2f x_prev, cv::Point2f x_cur, cv::Point2f gradient, const ScaleOptions& opt)
{
	CullResult r;
	const Eigen::Vector3d line = epipolarLine(F, x_prev);
	r.normal_error = normalError(line, x_cur);
	r.abs_cos = absCosToLine(line, gradient);
	// Written as !(kept) so that NaN culls.
	if (opt.cull_epipolar && !(r.normal_error < opt.epipolar_max_error)) r.rejected_by = Stage::Epipolar;
	else if (opt.cull_gradient && !(r.abs_cos > opt.min_abs_cos)) r.rejected_by = Stage::Gradient;
	return r;
}
}  // namespace vlo::scale
