#include <vlo/core/atomic_file.h>
#include <vlo/eval/report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace vlo
{
namespace
{
constexpr double kDeg = 180.0 / M_PI;

std::string num(std::optional<double> v)
{
	if (!v || !std::isfinite(*v)) return "null";
	char buf[32];
	std::snprintf(buf, sizeof buf, "%.10g", *v);
	return buf;
}

std::string str(const std::string& s)
{
	std::string o = "\"";
	for (const char c : s)
	{
		if (c == '"' || c == '\\')
			o += std::string("\\") + c;
		else if (static_cast<unsigned char>(c) < 0x20)
		{
			char buf[8];
			std::snprintf(buf, sizeof buf, "\\u%04x", c);
			o += buf;
		}
		else
			o += c;
	}
	return o + "\"";
}

std::string noteOrNull(const std::string& s) { return s.empty() ? "null" : str(s); }

std::string metricName(const EvalOptions& o)
{
	return o.ate && o.kitti && o.rpe ? "all" : o.ate ? "ate" : o.kitti ? "kitti" : "rpe";
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
	return {100 * r.kitti->t_err, kDeg * r.kitti->r_err, 100 * kDeg * r.kitti->r_err};
}
}  // namespace

std::string toJson(const EvalReport& r)
{
	const auto& a = r.association;
	const auto k = kittiNumbers(r);
	std::optional<double> ate, ate_mean, ate_max, ate_pct, are, scale;
	if (r.ate)
	{
		ate = r.ate->ate_rmse_m, ate_mean = r.ate->ate_mean_m, ate_max = r.ate->ate_max_m;
		are = r.ate->are_rmse_deg, scale = r.ate->sim3_scale;
		if (r.gt_length_m > 0) ate_pct = 100 * r.ate->ate_rmse_m / r.gt_length_m;
	}
	std::ostringstream o;
	o << "{\n";
	o << "  \"gt\": " << str(r.options.gt_name) << ",\n  \"est\": " << str(r.options.est_name) << ",\n";
	o << "  \"metric\": " << str(metricName(r.options)) << ",\n  \"align\": " << str(toString(r.options.align)) << ",\n";
	o << "  \"n_matched\": " << a.matched() << ",\n  \"n_est\": " << a.n_est << ",\n  \"n_gt\": " << a.n_gt << ",\n";
	o << "  \"n_dropped_outside_gt\": " << a.n_outside_span << ",\n  \"n_dropped_gt_gap\": " << a.n_in_gap << ",\n";
	o << "  \"max_dt_s\": " << num(a.max_gap_used_s) << ",\n";
	o << "  \"gt_translation_only\": " << (r.options.gt_translation_only ? "true" : "false") << ",\n";
	o << "  \"gt_length_m\": " << num(r.gt_length_m) << ",\n  \"est_length_m\": " << num(r.est_length_m) << ",\n";
	o << "  \"ate_rmse_m\": " << num(ate) << ",\n  \"ate_mean_m\": " << num(ate_mean) << ",\n";
	o << "  \"ate_max_m\": " << num(ate_max) << ",\n  \"ate_pct_of_length\": " << num(ate_pct) << ",\n";
	o << "  \"are_rmse_deg\": " << num(are) << ",\n  \"sim3_scale\": " << num(scale) << ",\n";
	o << "  \"ate_note\": " << noteOrNull(r.ate_note) << ",\n  \"are_note\": " << noteOrNull(r.are_note) << ",\n";
	o << "  \"kitti_frame\": " << str(r.kitti_frame) << ",\n";
	o << "  \"kitti_t_err_pct\": " << num(k.t_pct) << ",\n  \"kitti_r_err_deg_per_m\": " << num(k.r_deg_m) << ",\n";
	o << "  \"kitti_r_err_deg_per_100m\": " << num(k.r_deg_100m) << ",\n";
	o << "  \"kitti_segments\": " << (r.kitti ? std::to_string(r.kitti->segments.size()) : "null") << ",\n";
	o << "  \"kitti_per_length\": [";
	if (r.kitti)
		for (std::size_t i = 0; i < r.kitti->per_length.size(); ++i)
		{
			const auto& s = r.kitti->per_length[i];
			o << (i ? ",\n" : "\n") << "    {\"length_m\": " << num(s.length) << ", \"segments\": " << s.n
			  << ", \"t_err_pct\": " << num(100 * s.t_err) << ", \"r_err_deg_per_m\": " << num(kDeg * s.r_err)
			  << ", \"r_err_deg_per_100m\": " << num(100 * kDeg * s.r_err) << "}";
		}
	o << (r.kitti && !r.kitti->per_length.empty() ? "\n  ],\n" : "],\n");
	o << "  \"kitti_note\": " << noteOrNull(r.kitti_note) << ",\n";
	std::optional<double> rt, rr, rx, ry, rz, cvt, cvr;
	if (r.rpe)
	{
		rt = r.rpe->t_rmse_m, rr = r.rpe->r_rmse_deg, cvt = r.rpe->cv_t_rmse_m, cvr = r.rpe->cv_r_rmse_deg;
		rx = r.rpe->t_rmse_axes_m.x(), ry = r.rpe->t_rmse_axes_m.y(), rz = r.rpe->t_rmse_axes_m.z();
	}
	o << "  \"rpe_t_rmse_m\": " << num(rt) << ",\n  \"rpe_r_rmse_deg\": " << num(rr) << ",\n";
	o << "  \"rpe_t_rmse_axes_m\": [" << num(rx) << ", " << num(ry) << ", " << num(rz) << "],\n";
	o << "  \"gt_constant_velocity_t_rmse_m\": " << num(cvt) << ",\n  \"gt_constant_velocity_r_rmse_deg\": " << num(cvr) << ",\n";
	o << "  \"rpe_note\": " << noteOrNull(r.rpe_note) << "\n}\n";
	return o.str();
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
	o << "path length:  ground truth " << fmt("%.2f", r.gt_length_m) << " m, estimate " << fmt("%.2f", r.est_length_m)
	  << " m\n\n";
	const auto row = [&](const std::string& name, const std::string& value) {
		std::string n = "  " + name;
		n.resize(std::max<std::size_t>(n.size() + 1, 30), ' ');
		o << n << value << "\n";
	};
	const std::string al = std::string("(") + toString(r.options.align) + " aligned)";
	if (r.ate)
	{
		row("ATE RMSE " + al, fmt("%.4f m", r.ate->ate_rmse_m) +
				(r.gt_length_m > 0 ? fmt("  (%.3f %% of length)", 100 * r.ate->ate_rmse_m / r.gt_length_m) : ""));
		row("ARE RMSE " + al, r.ate->are_rmse_deg ? fmt("%.4f deg", *r.ate->are_rmse_deg) : "n/a: " + r.are_note);
		row("Sim(3) scale", r.ate->sim3_scale ? fmt("%.5f", *r.ate->sim3_scale) : "n/a: the estimate does not move");
	}
	else
		row("ATE / ARE", "n/a: " + r.ate_note);
	const auto k = kittiNumbers(r);
	if (k.t_pct)
	{
		const std::string seg = " (" + std::to_string(r.kitti->segments.size()) + " segments, frame: " + r.kitti_frame + ")";
		row("KITTI t_err", fmt("%.4f %%", *k.t_pct) + seg);
		row("KITTI r_err", fmt("%.6f deg/m", *k.r_deg_m) + fmt("  = %.4f deg/100m", *k.r_deg_100m));
		o << "\n  length [m]  segments  t_err [%]  r_err [deg/100m]\n";
		for (const auto& s : r.kitti->per_length)
			o << fmt("  %10.0f", s.length) << fmt("  %8.0f", static_cast<double>(s.n)) << fmt("  %9.4f", 100 * s.t_err)
			  << fmt("  %16.4f", 100 * kDeg * s.r_err) << "\n";
	}
	else
		row("KITTI t_err / r_err", "n/a: " + r.kitti_note);
	if (r.rpe)
	{
		const auto& e = *r.rpe;
		o << "\n";
		row("RPE per step, RMS", fmt("%.4f m", e.t_rmse_m) + fmt(" / %.4f deg", e.r_rmse_deg) + fmt("  (x %.4f", e.t_rmse_axes_m.x()) +
				fmt(", y %.4f", e.t_rmse_axes_m.y()) + fmt(", z %.4f m)", e.t_rmse_axes_m.z()));
		row("GT constant velocity", fmt("%.4f m", e.cv_t_rmse_m) + fmt(" / %.4f deg", e.cv_r_rmse_deg) +
				" RMS per step (each step predicted by the one before)");
	}
	else
		row("RPE", "n/a: " + r.rpe_note);
	return o.str();
}
}  // namespace vlo
