#include <vlo/core/error.h>
#include <vlo/eval/evaluate.h>
#include <vlo/eval/trajectory_alignment.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <sstream>

namespace vlo::eval
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
	if (s != "all" && s != "ate" && s != "kitti" && s != "rpe" && s != "revisit")
		failInput("--metric", "unknown metric '" + s + "' (expected kitti, ate, rpe, revisit or all)");
	opts.ate = s == "all" || s == "ate";
	opts.kitti = s == "all" || s == "kitti";
	opts.rpe = s == "all" || s == "rpe";
	opts.revisit = s == "all" || s == "revisit";
}

EvalReport evaluate(const Trajectory& gt, const Trajectory& est, const EvalOptions& opts)
{
	EvalReport r;
	r.options = opts;
	r.association = associate(gt, est, opts.association);
	const Association& a = r.association;
	if (a.matched() == 0)
		failInput(opts.est_name,
			"no pose overlaps the ground truth " + opts.gt_name + " in time (estimate " + span(est) +
				", ground truth " + span(gt) + ")");
	if (a.matched() < 3)
		failInput(opts.est_name,
			"only " + std::to_string(a.matched()) + " poses overlap the ground truth " + opts.gt_name +
				" in time; at least 3 are needed");
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

	if (!opts.revisit) r.revisit_note = "not requested (--metric)";
	else if (opts.gt_translation_only)
		r.revisit_note = "needs full ground-truth poses; the ground truth is translation-only";
	else
	{
		r.revisit = computeRevisitError(a.gt, a.est, opts.revisit_options);
		if (r.revisit->empty())
		{
			std::ostringstream s;
			s << "no revisit: the ground truth never comes back within " << opts.revisit_options.radius_m
			  << " m of a place after at least " << opts.revisit_options.min_path_m << " m of path";
			r.revisit_note = s.str();
		}
	}

	r.kitti_frame = opts.cam0_T_vehicle ? "camera 0" : "as given";
	if (!opts.kitti)
		r.kitti_note = "not requested (--metric)";
	else if (opts.gt_translation_only)
		r.kitti_note = "needs full ground-truth poses; the ground truth is translation-only";
	else
	{
		const Trajectory kgt = opts.cam0_T_vehicle ? io::vehicleToCamera(a.gt, *opts.cam0_T_vehicle) : a.gt;
		const Trajectory kest = opts.cam0_T_vehicle ? io::vehicleToCamera(a.est, *opts.cam0_T_vehicle) : a.est;
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
	r.warnings = plausibilityWarnings(r);
	return r;
}

Trajectory alignedEstimate(const EvalReport& r)
{
	return r.ate ? transformed(r.association.est, r.ate->alignment) : r.association.est;
}

namespace
{
/// Positions along a line (a straight drive): an alignment's rotation about that line is then
/// arbitrary, and so is the ARE.
bool collinear(const Trajectory& tr)
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	for (const auto& p : tr) mean += p.pose.translation();
	mean /= double(tr.size());
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	for (const auto& p : tr) cov += (p.pose.translation() - mean) * (p.pose.translation() - mean).transpose();
	const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues();  // increasing
	return ev(1) < 1e-2 * ev(2);
}
}  // namespace

std::vector<std::string> plausibilityWarnings(const EvalReport& r)
{
	std::vector<std::string> w;
	const Association& a = r.association;
	const std::string suffix = ": is " + r.options.gt_name + " the ground truth of this drive?";
	std::ostringstream s;
	s.precision(3);
	if (2 * a.matched() < a.n_est)
	{
		s << "only " << a.matched() << " of " << a.n_est << " estimated poses fall within the ground truth's time span" << suffix;
		w.push_back(s.str());
		s.str("");
	}
	if (r.ate && r.ate->are_rmse_deg && *r.ate->are_rmse_deg > 30 && !collinear(a.gt))
	{
		s << "the rotation error after alignment is " << *r.ate->are_rmse_deg << " deg RMS" << suffix;
		w.push_back(s.str());
		s.str("");
	}
	if (r.ate && r.ate->are_roll_from_orientations_deg)
	{
		s << "the path is nearly straight: its positions leave the alignment's rotation about the direction of travel "
		  << "uncertain by " << r.ate->are_roll_uncertainty_deg << " deg, so the ARE takes that rotation from the "
		  << "orientations (" << *r.ate->are_roll_from_orientations_deg << " deg from the positions' fit; ATE keeps it)";
		w.push_back(s.str());
		s.str("");
	}
	const bool scaled = r.options.align == Alignment::Sim3;
	if (!scaled && r.gt_length_m > 1 && (r.est_length_m > 2 * r.gt_length_m || 2 * r.est_length_m < r.gt_length_m))
	{
		s << "the estimate's path is " << r.est_length_m << " m against " << r.gt_length_m
		  << " m of ground truth over the same times (an unscaled monocular VO needs --align sim3)" << suffix;
		w.push_back(s.str());
	}
	return w;
}
}  // namespace vlo::eval
