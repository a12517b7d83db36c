#include <vlo/batch/tables.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace vlo::batch
{
namespace
{
std::string field(const std::string& s)
{
	if (s.find_first_of(",\"\n") == std::string::npos) return s;
	std::string q = "\"";
	for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
	return q + "\"";
}

std::string number(double v)
{
	if (!std::isfinite(v)) return "";
	char buf[32];
	std::snprintf(buf, sizeof buf, "%.6g", v);
	return buf;
}

const char* statusName(RunStatus s)
{
	return s == RunStatus::Ok ? "ok" : s == RunStatus::Failed ? "failed"
															  : "not run";
}

/// vlo-eval JSON keys, in column order (doc/EVALUATION.md); later additions last (the revisit error,
/// the path ratio), so that the columns before them keep their places.
const char* const kEvalKeys[] = {"ate_rmse_m", "are_rmse_deg", "sim3_scale", "kitti_t_err_pct", "kitti_r_err_deg_per_m",
	"kitti_segments", "rpe_t_rmse_m", "rpe_r_rmse_deg", "n_matched", "gt_length_m", "revisit_pairs", "revisit_t_rmse_m",
	"revisit_t_max_m", "revisit_r_rmse_deg", "revisit_r_max_deg", "path_ratio"};
}  // namespace

std::string csvResults(const std::vector<RunResult>& results)
{
	std::ostringstream o;
	o << "sequence,config,trajectory,status,align";
	for (const char* k : kEvalKeys) o << "," << k;
	o << ",frames,ms_per_frame,error\n";
	for (const auto& r : results)
	{
		// A trajectory's row is ok or failed by its own evaluation; a run without one by the run.
		const auto row = [&](const TrajectoryResult* t) {
			const std::string status = t ? (t->error.empty() ? "ok" : "failed") : statusName(r.status);
			o << r.sequence << "," << r.config << "," << (t ? t->name : "") << "," << status << "," << r.align;
			for (const char* k : kEvalKeys) o << "," << (t ? number(t->eval.number(k)) : "");
			o << "," << number(r.frames) << "," << number(r.ms_per_frame) << "," << field(t ? t->error : r.error) << "\n";
		};
		if (r.trajectories.empty()) row(nullptr);
		for (const auto& t : r.trajectories) row(&t);
	}
	return o.str();
}
}  // namespace vlo::batch
