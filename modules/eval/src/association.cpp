#include <vlo/core/error.h>
#include <vlo/core/se3.h>
#include <vlo/eval/association.h>

#include <algorithm>

namespace vlo::eval
{
namespace
{
void requireIncreasing(const Trajectory& traj, const char* what)
{
	for (std::size_t i = 1; i < traj.size(); ++i)
		if (!(traj[i].t > traj[i - 1].t))
			failInput(what, "timestamps are not strictly increasing at pose " + std::to_string(i));
}
}  // namespace

double medianTimeStep(const Trajectory& traj)
{
	if (traj.size() < 2) return 0;
	std::vector<double> dt(traj.size() - 1);
	for (std::size_t i = 1; i < traj.size(); ++i) dt[i - 1] = traj[i].t - traj[i - 1].t;
	std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
	return dt[dt.size() / 2];
}

Association associate(const Trajectory& gt, const Trajectory& est, const AssociationOptions& opts)
{
	requireIncreasing(gt, "ground truth");
	requireIncreasing(est, "estimate");
	Association a;
	a.n_est = est.size();
	a.n_gt = gt.size();
	a.max_gap_used_s = opts.max_gap_s > 0 ? opts.max_gap_s : 3.0 * medianTimeStep(gt);
	if (gt.empty())
	{
		a.n_outside_span = est.size();
		return a;
	}
	const double t0 = gt.front().t, t1 = gt.back().t, eps = opts.end_tolerance_s;
	const auto byTime = [](const StampedPose& p, double t) { return p.t < t; };
	for (const auto& e : est)
	{
		if (e.t < t0 - eps || e.t > t1 + eps)
		{
			++a.n_outside_span;
			continue;
		}
		StampedPose g;
		g.t = e.t;
		// First GT sample at or after e.t; the bracketing interval is [k-1, k].
		const auto it = std::lower_bound(gt.begin(), gt.end(), e.t, byTime);
		if (it == gt.end())
			g.pose = gt.back().pose;  // within eps after the end
		else if (it->t - e.t <= eps || it == gt.begin())
			g.pose = it->pose;  // (nearly) on a sample, or within eps before the start
		else
		{
			const auto& A = *(it - 1);
			const auto& B = *it;
			if (B.t - A.t > a.max_gap_used_s)
			{
				++a.n_in_gap;
				continue;
			}
			g.pose = interpolate(A.pose, B.pose, (e.t - A.t) / (B.t - A.t));
		}
		a.est.push_back(e);
		a.gt.push_back(g);
	}
	return a;
}
}  // namespace vlo::eval
