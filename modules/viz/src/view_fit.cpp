#include "view_fit.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace vlo::viz
{
std::optional<cv::Point2d> ViewCamera::project(const Eigen::Vector3d& p) const
{
	const Eigen::Vector3d q = world_T_cam.inverse() * p;
	if (q.z() < near) return std::nullopt;
	return cv::Point2d(f * q.x() / q.z() + cx, f * q.y() / q.z() + cy);
}

namespace
{
Eigen::Matrix3d lookRotation(double az, double el)
{
	const Eigen::Vector3d eye(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
	const Eigen::Vector3d fwd = -eye;
	const Eigen::Vector3d right = fwd.cross(Eigen::Vector3d::UnitZ()).normalized();
	Eigen::Matrix3d R;
	R << right, fwd.cross(right), fwd;  // columns: x right, y down, z forward
	return R;
}
}  // namespace

ViewCamera fitView(const std::vector<Eigen::Vector3d>& pts, double az, double el, double fovy, const cv::Rect& content,
	int width, int height)
{
	Eigen::Vector3d lo = pts.front(), hi = pts.front();
	for (const auto& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
	const Eigen::Vector3d target = 0.5 * (lo + hi);
	const double radius = std::max(0.5 * (hi - lo).norm(), 1.0);

	ViewCamera v;
	v.width = width, v.height = height;
	v.f = 0.5 * height / std::tan(0.5 * fovy);
	const Eigen::Matrix3d R = lookRotation(az, el);
	const Eigen::Vector3d eyeDir = -R.col(2);
	// Image extents (relative to the principal point) of all points at distance D; nothing if any is
	// behind the camera.
	auto extents = [&](double D, cv::Rect2d& box) {
		double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
		const Eigen::Vector3d C = target + D * eyeDir;
		for (const auto& p : pts)
		{
			const Eigen::Vector3d q = R.transpose() * (p - C);
			if (q.z() < 0.02 * radius) return false;
			const double u = v.f * q.x() / q.z(), w = v.f * q.y() / q.z();
			u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, w), v1 = std::max(v1, w);
		}
		box = cv::Rect2d(u0, v0, u1 - u0, v1 - v0);
		return true;
	};
	auto fits = [&](double D) {
		cv::Rect2d b;
		return extents(D, b) && b.width <= content.width && b.height <= content.height;
	};
	double dLo = 0.01 * radius, dHi = 100 * radius;
	for (int i = 0; i < 50; ++i)
	{
		const double mid = std::sqrt(dLo * dHi);
		(fits(mid) ? dHi : dLo) = mid;
	}
	cv::Rect2d box;
	extents(dHi, box);
	v.world_T_cam.linear() = R;
	v.world_T_cam.translation() = target + dHi * eyeDir;
	// Shift the principal point so that the framed points sit centred in `content`.
	v.cx = content.x + 0.5 * content.width - (box.x + 0.5 * box.width);
	v.cy = content.y + 0.5 * content.height - (box.y + 0.5 * box.height);
	double zmin = INFINITY, zmax = 0;
	for (const auto& p : pts)
	{
		const double z = (v.world_T_cam.inverse() * p).z();
		zmin = std::min(zmin, z), zmax = std::max(zmax, z);
	}
	v.near = std::max(0.05, 0.5 * zmin), v.far = 1.5 * zmax + 1;
	return v;
}

double acrossAzimuth(const std::vector<Eigen::Vector3d>& pts)
{
	Eigen::Vector2d mean = Eigen::Vector2d::Zero();
	for (const auto& p : pts) mean += p.head<2>();
	mean /= double(std::max<size_t>(pts.size(), 1));
	Eigen::Matrix2d C = Eigen::Matrix2d::Zero();
	for (const auto& p : pts) C += (p.head<2>() - mean) * (p.head<2>() - mean).transpose();
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(C);
	Eigen::Vector2d major = es.eigenvectors().col(1);
	if (major.x() < 0) major = -major;  // deterministic side: x grows left to right, as in the top-down view
	// Look from the side of the major axis (minus 90 degrees), turned 30 degrees for depth cues.
	return std::atan2(major.y(), major.x()) - M_PI / 2 + M_PI / 6;
}
}  // namespace vlo::viz
