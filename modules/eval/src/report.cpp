#include <vlo/core/atomic_file.h>
#include <vlo/core/units.h>
#include <vlo/eval/report.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace vlo::eval
{
namespace
{
/// Absent or not finite: null.
nlohmann::ordered_json num(std::optional<double> v)
{
	if (!v || !std::isfinite(*v)) return nullptr;
	return *v;
}

nlohmann::ordered_json noteOrNull(const std::string& s) { return s.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(s); }

std::string metricName(const EvalOptions& o)
{
	if (o.ate && o.kitti && o.rpe && o.revisit) return "all";
	return o.ate ? "ate" : o.kitti ? "kitti"
		: o.rpe                    ? "rpe"
								   : "revisit";
}

std::string fmt(const char* f, double v)
{
	char buf[64];
	std::snprintf(buf, sizeof buf, f, v);
	return buf;
}

/// The KITTI numbers, empty when not computed or without segments.
struct KittiNumbers
{
	std::optional<double> t_pct, r_deg_m, r_deg_100m;
};
KittiNumbers kittiNumbers(const EvalReport& r)
{
	if (!r.kitti || r.kitti->empty()) return {};
	return {100 * r.kitti->t_err, kDegPerRad * r.kitti->r_err, 100 * kDegPerRad * r.kitti->r_err};
}

/// The revisit error's numbers, empty when not computed or without a revisit.
struct RevisitNumbers
{
	std::optional<double> t_rmse, t_max, r_rmse, r_max;
};
/// The estimate's path over the truth's, on the matched poses (none without a truth path).
std::optional<double> pathRatio(const EvalReport& r)
{
	if (!(r.gt_length_m > 0)) return std::nullopt;
	return r.est_length_m / r.gt_length_m;
}

RevisitNumbers revisitNumbers(const EvalReport& r)
{
	if (!r.revisit || r.revisit->empty()) return {};
	return {r.revisit->t_rmse_m, r.revisit->t_max_m, r.revisit->r_rmse_deg, r.revisit->r_max_deg};
}
}  // namespace

std::string toJson(const EvalReport& r)
{
	const auto& a = r.association;
	const auto k = kittiNumbers(r);
	std::optional<double> ate, ate_mean, ate_max, ate_pct, are, are_roll, scale, ax, ay, az;
	if (r.ate)
	{
		ate = r.ate->ate_rmse_m, ate_mean = r.ate->ate_mean_m, ate_max = r.ate->ate_max_m;
		if (const auto& axes = r.ate->ate_rmse_axes_m) ax = axes->x(), ay = axes->y(), az = axes->z();
		are = r.ate->are_rmse_deg, are_roll = r.ate->are_roll_from_orientations_deg, scale = r.ate->sim3_scale;
		if (r.gt_length_m > 0) ate_pct = 100 * r.ate->ate_rmse_m / r.gt_length_m;
	}
	nlohmann::ordered_json perLength = nlohmann::ordered_json::array();
	if (r.kitti)
		for (const auto& s : r.kitti->per_length)
			perLength.push_back({{"length_m", num(s.length)}, {"segments", s.n}, {"t_err_pct", num(100 * s.t_err)},
				{"r_err_deg_per_m", num(kDegPerRad * s.r_err)}, {"r_err_deg_per_100m", num(100 * kDegPerRad * s.r_err)}});
	std::optional<double> rt, rr, rx, ry, rz, cvt, cvr;
	if (r.rpe)
	{
		rt = r.rpe->t_rmse_m, rr = r.rpe->r_rmse_deg, cvt = r.rpe->cv_t_rmse_m, cvr = r.rpe->cv_r_rmse_deg;
		rx = r.rpe->t_rmse_axes_m.x(), ry = r.rpe->t_rmse_axes_m.y(), rz = r.rpe->t_rmse_axes_m.z();
	}
	const auto v = revisitNumbers(r);
	const nlohmann::ordered_json revisitPairs = r.revisit ? nlohmann::ordered_json(r.revisit->pairs.size()) : nlohmann::ordered_json();
	const nlohmann::ordered_json j = {{"gt", r.options.gt_name}, {"est", r.options.est_name},
		{"metric", metricName(r.options)}, {"align", toString(r.options.align)}, {"n_matched", a.matched()},
		{"n_est", a.n_est}, {"n_gt", a.n_gt}, {"n_dropped_outside_gt", a.n_outside_span},
		{"n_dropped_gt_gap", a.n_in_gap}, {"max_dt_s", num(a.max_gap_used_s)},
		{"gt_translation_only", r.options.gt_translation_only}, {"gt_length_m", num(r.gt_length_m)},
		{"est_length_m", num(r.est_length_m)}, {"path_ratio", num(pathRatio(r))}, {"ate_rmse_m", num(ate)}, {"ate_mean_m", num(ate_mean)},
		{"ate_max_m", num(ate_max)}, {"ate_rmse_axes_m", {num(ax), num(ay), num(az)}}, {"ate_pct_of_length", num(ate_pct)}, {"are_rmse_deg", num(are)},
		{"are_roll_from_orientations_deg", num(are_roll)}, {"sim3_scale", num(scale)}, {"ate_note", noteOrNull(r.ate_note)}, {"are_note", noteOrNull(r.are_note)},
		{"kitti_frame", r.kitti_frame}, {"kitti_t_err_pct", num(k.t_pct)}, {"kitti_r_err_deg_per_m", num(k.r_deg_m)},
		{"kitti_r_err_deg_per_100m", num(k.r_deg_100m)},
		{"kitti_segments", r.kitti ? nlohmann::ordered_json(r.kitti->segments.size()) : nlohmann::ordered_json()},
		{"kitti_per_length", perLength}, {"kitti_note", noteOrNull(r.kitti_note)}, {"rpe_t_rmse_m", num(rt)},
		{"rpe_r_rmse_deg", num(rr)}, {"rpe_t_rmse_axes_m", {num(rx), num(ry), num(rz)}},
		{"gt_constant_velocity_t_rmse_m", num(cvt)}, {"gt_constant_velocity_r_rmse_deg", num(cvr)},
		{"rpe_note", noteOrNull(r.rpe_note)}, {"revisit_pairs", revisitPairs},
		{"revisit_t_rmse_m", num(v.t_rmse)}, {"revisit_t_max_m", num(v.t_max)}, {"revisit_r_rmse_deg", num(v.r_rmse)},
		{"revisit_r_max_deg", num(v.r_max)}, {"revisit_radius_m", num(r.options.revisit_options.radius_m)},
		{"revisit_min_path_m", num(r.options.revisit_options.min_path_m)}, {"revisit_note", noteOrNull(r.revisit_note)}};
	return j.dump(2) + "\n";
}

void writeJson(const std::string& path, const EvalReport& r)
{
	AtomicOutputFile f(path);
	f.stream() << toJson(r);
	f.commit();
}

std::string formatTable(const EvalReport& r)
{
	const auto& a = r.association;
	std::ostringstream o;
	o << "ground truth: " << r.options.gt_name << " (" << a.n_gt << " poses"
	  << (r.options.gt_translation_only ? ", translation only" : "") << ")\n";
	o << "estimate:     " << r.options.est_name << " (" << a.n_est << " poses)\n";
	o << "matched:      " << a.matched() << " poses; dropped " << a.n_outside_span << " outside the ground truth's span, "
	  << a.n_in_gap << " in ground-truth gaps > " << fmt("%.3g", a.max_gap_used_s) << " s\n";
	o << "path length:  ground truth " << fmt("%.2f", r.gt_length_m) << " m, estimate " << fmt("%.2f", r.est_length_m) << " m";
	if (const auto ratio = pathRatio(r)) o << " (ratio " << fmt("%.4f", *ratio) << ")";
	o << "\n\n";
	const auto row = [&](const std::string& name, const std::string& value) {
		std::string n = "  " + name;
		n.resize(std::max<std::size_t>(n.size() + 1, 30), ' ');
		o << n << value << "\n";
	};
	const std::string al = std::string("(") + toString(r.options.align) + " aligned)";
	if (r.ate)
	{
		const std::string of_length = r.gt_length_m > 0 ? fmt("  (%.3f %% of length)", 100 * r.ate->ate_rmse_m / r.gt_length_m) : "";
		row("ATE RMSE " + al, fmt("%.4f m", r.ate->ate_rmse_m) + of_length);
		if (const auto& e = r.ate->ate_rmse_axes_m)
			row("ATE RMSE per truth axis", fmt("x %.4f", e->x()) + fmt(", y %.4f", e->y()) + fmt(", z %.4f m", e->z()));
		const auto& roll = r.ate->are_roll_from_orientations_deg;
		const std::string roll_note = roll ? "  (roll about the path from the orientations)" : "";
		row("ARE RMSE " + al, r.ate->are_rmse_deg ? fmt("%.4f deg", *r.ate->are_rmse_deg) + roll_note : "n/a: " + r.are_note);
		row("Sim(3) scale", r.ate->sim3_scale ? fmt("%.5f", *r.ate->sim3_scale) : "n/a: the estimate does not move");
	}
	else
		row("ATE / ARE", "n/a: " + r.ate_note);
	if (r.options.revisit)  // not requested: no line, so that the other metrics' tables stay as they were
	{
		const auto v = revisitNumbers(r);
		const auto& ro = r.options.revisit_options;
		const std::string where = fmt(" within %g m", ro.radius_m) + fmt(" after >= %g m of path", ro.min_path_m);
		if (v.t_rmse)
		{
			row("Revisit error, translation", fmt("%.4f m RMS", *v.t_rmse) + fmt(", %.4f m max", *v.t_max) + "  (" + std::to_string(r.revisit->pairs.size()) + " pairs:" + where + ")");
			row("Revisit error, rotation", fmt("%.4f deg RMS", *v.r_rmse) + fmt(", %.4f deg max", *v.r_max));
		}
		else if (r.revisit)
			row("Revisit error", "no revisit (0 pairs:" + where + ")");
		else
			row("Revisit error", "n/a: " + r.revisit_note);
	}
	const auto k = kittiNumbers(r);
	if (k.t_pct)
	{
		const std::string seg = " (" + std::to_string(r.kitti->segments.size()) + " segments, frame: " + r.kitti_frame + ")";
		row("KITTI t_err", fmt("%.4f %%", *k.t_pct) + seg);
		row("KITTI r_err", fmt("%.6f deg/m", *k.r_deg_m) + fmt("  = %.4f deg/100m", *k.r_deg_100m));
		o << "\n  length [m]  segments  t_err [%]  r_err [deg/100m]\n";
		for (const auto& s : r.kitti->per_length)
			o << fmt("  %10.0f", s.length) << fmt("  %8.0f", static_cast<double>(s.n)) << fmt("  %9.4f", 100 * s.t_err)
			  << fmt("  %16.4f", 100 * kDegPerRad * s.r_err) << "\n";
	}
	else
		row("KITTI t_err / r_err", "n/a: " + r.kitti_note);
	if (r.rpe)
	{
		const auto& e = *r.rpe;
		o << "\n";
		row("RPE per step, RMS",
			fmt("%.4f m", e.t_rmse_m) + fmt(" / %.4f deg", e.r_rmse_deg) +
				fmt("  (x %.4f", e.t_rmse_axes_m.x()) + fmt(", y %.4f", e.t_rmse_axes_m.y()) +
				fmt(", z %.4f m)", e.t_rmse_axes_m.z()));
		row("GT constant velocity",
			fmt("%.4f m", e.cv_t_rmse_m) + fmt(" / %.4f deg", e.cv_r_rmse_deg) +
				" RMS per step (each step predicted by the one before)");
	}
	else
		row("RPE", "n/a: " + r.rpe_note);
	return o.str();
}
}  // namespace vlo::eval
