#include <vlo/core/error.h>
#include <vlo/eval/ate.h>
#include <vlo/eval/umeyama.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace vlo
{
namespace
{
/// Each alignment with its name on the command line, in plans and in reports.
const std::pair<Alignment, const char*> kAlignmentNames[] = {
	{Alignment::None, "none"}, {Alignment::SE3, "se3"}, {Alignment::Sim3, "sim3"}};
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
	double sq_t = 0, sq_r = 0, sum_t = 0;
	for (std::size_t i = 0; i < est.size(); ++i)
	{
		const double e = errors[i];
		sq_t += e * e;
		sum_t += e;
		r.ate_max_m = std::max(r.ate_max_m, e);
		const Eigen::Matrix3d dR = gt[i].pose.linear().transpose() * r.alignment.R * est[i].pose.linear();
		const double a = rotationAngle(dR);
		sq_r += a * a;
	}
	const double n = static_cast<double>(est.size());
	r.ate_rmse_m = std::sqrt(sq_t / n);
	r.ate_mean_m = sum_t / n;
	if (gt_has_rotation) r.are_rmse_deg = std::sqrt(sq_r / n) * 180.0 / M_PI;
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
}  // namespace vlo
