#include <vlo/core/error.h>
#include <vlo/eval/ate.h>
#include <vlo/eval/umeyama.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace vlo::eval
{
namespace
{
/// Each alignment with its name on the command line, in plans and in reports.
const std::pair<Alignment, const char*> kAlignmentNames[] = {
	{Alignment::None, "none"}, {Alignment::SE3, "se3"}, {Alignment::Sim3, "sim3"}};
/// The alignment's rotation for the ARE. The positions fix its rotation about the path's main direction d only
/// as far as they spread across d: a rotation by x about d moves them by x * sqrt(spread) RMS, so position
/// errors of ate_rmse leave it uncertain by ate_rmse / sqrt(spread). On a nearly straight path (spread
/// across d below a tenth of that along it) where this exceeds 1 deg (tens of degrees on KITTI's straight
/// snippets), the rotation about d is the one that best aligns the orientations instead: Q(theta) about d
/// maximising trace(Q N), N = sum R P_i G_i^T, in closed form. A curved path keeps the positions' fit,
/// however poor the estimate.
Eigen::Matrix3d rotationForAre(const Trajectory& gt, const Trajectory& est, const Eigen::Matrix3d& R, double ate_rmse,
	AteResult& r)
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	for (const auto& p : gt) mean += p.pose.translation();
	mean /= double(gt.size());
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	for (const auto& p : gt) cov += (p.pose.translation() - mean) * (p.pose.translation() - mean).transpose();
	cov /= double(gt.size());
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);  // eigenvalues increasing
	const double spread = std::max(0.0, eig.eigenvalues()(0) + eig.eigenvalues()(1));
	const double one_deg = M_PI / 180.0;
	r.are_roll_uncertainty_deg = spread > 0 ? std::atan(ate_rmse / std::sqrt(spread)) / one_deg : 90.0;
	const bool nearly_straight = spread < 0.01 * eig.eigenvalues()(2);  // 1/10 of the extent, squared
	if (!nearly_straight || r.are_roll_uncertainty_deg <= 1.0) return R;

	const Eigen::Vector3d d = eig.eigenvectors().col(2);
	Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
	for (std::size_t i = 0; i < gt.size(); ++i) N += R * est[i].pose.linear() * gt[i].pose.linear().transpose();
	Eigen::Matrix3d K;
	K << 0, -d.z(), d.y(), d.z(), 0, -d.x(), -d.y(), d.x(), 0;
	const double theta = std::atan2((K * N).trace(), N.trace() - d.dot(N * d));
	r.are_roll_from_orientations_deg = theta / one_deg;
	return Eigen::AngleAxisd(theta, d).toRotationMatrix() * R;
}
}  // namespace

Alignment parseAlignment(const std::string& s, const std::string& where)
{
	for (const auto& [a, name] : kAlignmentNames)
		if (s == name) return a;
	failInput(where, "unknown alignment '" + s + "' (expected none, se3 or sim3)");
}

const char* toString(Alignment a)
{
	for (const auto& [value, name] : kAlignmentNames)
		if (value == a) return name;
	return "?";
}

AteResult computeAte(const Trajectory& gt, const Trajectory& est, Alignment align, bool gt_has_rotation)
{
	if (gt.size() != est.size()) throw std::invalid_argument("computeAte: trajectories must be paired by index");
	if (est.size() < 3) failInput("alignment", "need at least 3 associated poses, got " + std::to_string(est.size()));
	std::vector<Eigen::Vector3d> src, dst;
	for (std::size_t i = 0; i < est.size(); ++i)
	{
		src.push_back(est[i].pose.translation());
		dst.push_back(gt[i].pose.translation());
	}
	AteResult r;
	r.n = est.size();
	if (align == Alignment::SE3) r.alignment = umeyama(src, dst, false);
	if (align == Alignment::Sim3) r.alignment = umeyama(src, dst, true);
	try
	{
		r.sim3_scale = align == Alignment::Sim3 ? r.alignment.s : umeyama(src, dst, true).s;
	}
	catch (const InputError&)
	{
		// A diagnostic only: a motionless estimate has no scale, which is not an error for SE(3).
	}

	const std::vector<double> errors = ateErrors(gt, est, r.alignment);
	double sq_t = 0, sum_t = 0;
	for (const double e : errors)
	{
		sq_t += e * e;
		sum_t += e;
		r.ate_max_m = std::max(r.ate_max_m, e);
	}
	const double n = static_cast<double>(est.size());
	r.ate_rmse_m = std::sqrt(sq_t / n);
	r.ate_mean_m = sum_t / n;
	if (!gt_has_rotation) return r;
	Eigen::Vector3d axes2 = Eigen::Vector3d::Zero();
	for (std::size_t i = 0; i < est.size(); ++i)
	{
		const Eigen::Vector3d e = r.alignment * Eigen::Vector3d(est[i].pose.translation()) - gt[i].pose.translation();
		axes2 += (gt[i].pose.linear().transpose() * e).cwiseAbs2();
	}
	r.ate_rmse_axes_m = (axes2 / n).cwiseSqrt();

	// Unaligned, the estimate's rotation is as given: nothing to choose.
	const Eigen::Matrix3d R = align == Alignment::None ? r.alignment.R : rotationForAre(gt, est, r.alignment.R, r.ate_rmse_m, r);
	double sq_r = 0;
	for (std::size_t i = 0; i < est.size(); ++i)
	{
		const double a = rotationAngle(gt[i].pose.linear().transpose() * R * est[i].pose.linear());
		sq_r += a * a;
	}
	r.are_rmse_deg = std::sqrt(sq_r / n) * 180.0 / M_PI;
	return r;
}

std::vector<double> ateErrors(const Trajectory& gt, const Trajectory& est, const Sim3& alignment)
{
	if (gt.size() != est.size()) throw std::invalid_argument("ateErrors: trajectories must be paired by index");
	std::vector<double> e(est.size());
	for (std::size_t i = 0; i < est.size(); ++i)
		e[i] = (gt[i].pose.translation() - alignment * Eigen::Vector3d(est[i].pose.translation())).norm();
	return e;
}
}  // namespace vlo::eval
