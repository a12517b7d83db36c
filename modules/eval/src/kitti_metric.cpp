#include <vlo/eval/association.h>
#include <vlo/eval/kitti_metric.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vlo::eval
{
namespace
{
constexpr std::size_t kNone = static_cast<std::size_t>(-1);

/// First frame whose distance exceeds dist[first] + len (strictly, as in the devkit), or npos.
std::size_t lastFrameFromSegmentLength(const std::vector<double>& dist, std::size_t first, double len)
{
	for (std::size_t i = first; i < dist.size(); ++i)
		if (dist[i] > dist[first] + len) return i;
	return kNone;
}

/// The devkit's angle: acos of the clamped trace term, not the more accurate atan2 form, so that
/// numbers match the benchmark's.
double devkitRotationError(const Eigen::Matrix3d& R)
{
	const double d = 0.5 * (R.trace() - 1.0);
	return std::acos(std::max(std::min(d, 1.0), -1.0));
}
}  // namespace

std::vector<double> trajectoryDistances(const Trajectory& traj)
{
	std::vector<double> dist(traj.empty() ? 0 : 1, 0.0);
	for (std::size_t i = 1; i < traj.size(); ++i)
		dist.push_back(dist.back() + (traj[i].pose.translation() - traj[i - 1].pose.translation()).norm());
	return dist;
}

KittiResult kittiMetric(const Trajectory& gt, const Trajectory& est, const KittiOptions& opts)
{
	if (gt.size() != est.size()) throw std::invalid_argument("kittiMetric: trajectories must be paired by index");
	if (opts.step == 0) throw std::invalid_argument("kittiMetric: step must be positive");
	KittiResult r;
	const std::vector<double> dist = trajectoryDistances(gt);
	const double period = medianTimeStep(gt);
	for (std::size_t first = 0; first < gt.size(); first += opts.step)
		for (const double len : opts.lengths)
		{
			const std::size_t last = lastFrameFromSegmentLength(dist, first, len);
			if (last == kNone) continue;
			const Eigen::Isometry3d dG = gt[first].pose.inverse() * gt[last].pose;
			const Eigen::Isometry3d dP = est[first].pose.inverse() * est[last].pose;
			const Eigen::Isometry3d E = dP.inverse() * dG;
			const double speed = period > 0 ? len / (period * double(last - first + 1)) : NAN;
			r.segments.push_back(
				{first, last, len, E.translation().norm() / len, devkitRotationError(E.linear()) / len, speed});
		}
	for (const double len : opts.lengths)
	{
		KittiLengthStats s;
		s.length = len;
		for (const auto& seg : r.segments)
			if (seg.length == len)
			{
				++s.n;
				s.t_err += seg.t_err;
				s.r_err += seg.r_err;
			}
		if (s.n == 0) continue;
		s.t_err /= s.n;
		s.r_err /= s.n;
		r.per_length.push_back(s);
	}
	for (const auto& seg : r.segments)
	{
		r.t_err += seg.t_err;
		r.r_err += seg.r_err;
	}
	if (!r.segments.empty())
	{
		r.t_err /= r.segments.size();
		r.r_err /= r.segments.size();
	}
	return r;
}
}  // namespace vlo::eval
