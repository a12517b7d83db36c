#include <vlo/core/error.h>
#include <vlo/eval/evaluate.h>

#include <algorithm>
#include <sstream>

namespace vlo
{
namespace
{
std::string span(const Trajectory& t)
{
	std::ostringstream s;
	s.precision(10);
	if (t.empty()) return "no poses";
	s << "[" << t.front().t << ", " << t.back().t << "] s";
	return s.str();
}
}  // namespace

void parseMetric(const std::string& s, EvalOptions& opts)
{
	if (s != "all" && s != "ate" && s != "kitti" && s != "rpe")
		failInput("--metric", "unknown metric '" + s + "' (expected kitti, ate, rpe or all)");
	opts.ate = s == "all" || s == "ate";
	opts.kitti = s == "all" || s == "kitti";
	opts.rpe = s == "all" || s == "rpe";
}

EvalReport evaluate(const Trajectory& gt, const Trajectory& est, const EvalOptions& opts)
{
	EvalReport r;
	r.options = opts;
	r.association = associate(gt, est, opts.association);
	const Association& a = r.association;
	if (a.matched() == 0)
		failInput(opts.est_name, "no pose overlaps the ground truth " + opts.gt_name + " in time (estimate " +
				span(est) + ", ground truth " + span(gt) + ")");
	if (a.matched() < 3)
		failInput(opts.est_name, "only " + std::to_string(a.matched()) + " poses overlap the ground truth " +
				opts.gt_name + " in time; at least 3 are needed");
	r.gt_length_m = pathLength(a.gt);
	r.est_length_m = pathLength(a.est);

	if (opts.ate)
	{
		r.ate = computeAte(a.gt, a.est, opts.align, !opts.gt_translation_only);
		if (opts.gt_translation_only) r.are_note = "ground truth is translation-only";
	}
	else
		r.ate_note = r.are_note = "not requested (--metric)";

	if (!opts.rpe) r.rpe_note = "not requested (--metric)";
	else if (opts.gt_translation_only) r.rpe_note = "needs full ground-truth poses; the ground truth is translation-only";
	else r.rpe = computeRpe(a.gt, a.est);

	r.kitti_frame = opts.cam0_T_vehicle ? "camera 0" : "as given";
	if (!opts.kitti)
		r.kitti_note = "not requested (--metric)";
	else if (opts.gt_translation_only)
		r.kitti_note = "needs full ground-truth poses; the ground truth is translation-only";
	else
	{
		const Trajectory kgt = opts.cam0_T_vehicle ? vehicleToCamera(a.gt, *opts.cam0_T_vehicle) : a.gt;
		const Trajectory kest = opts.cam0_T_vehicle ? vehicleToCamera(a.est, *opts.cam0_T_vehicle) : a.est;
		r.kitti = kittiMetric(kgt, kest, opts.kitti_options);
		if (r.kitti->empty())
		{
			const auto& L = opts.kitti_options.lengths;
			std::ostringstream s;
			s.precision(4);
			s << "no segment: the ground-truth path over the matched poses is " << pathLength(kgt)
			  << " m, not longer than the shortest segment length ("
			  << (L.empty() ? 0.0 : *std::min_element(L.begin(), L.end())) << " m)";
			r.kitti_note = s.str();
		}
	}
	return r;
}
}  // namespace vlo
