#include <vlo/batch/tables.h>
#include <vlo/batch/words.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

namespace vlo::batch
{
namespace
{
struct Row
{
	std::string config, trajectory;  ///< trajectory empty: the configuration left none anywhere
};

std::string fmt(const char* f, double a, double b = 0)
{
	char buf[64];
	std::snprintf(buf, sizeof buf, f, a, b);
	return buf;
}

std::string escape(const std::string& s)
{
	std::string o;
	for (const char c : s) o += c == '|' ? std::string("\\|") : std::string(1, c);
	return o;
}

const RunResult* findRun(const std::vector<RunResult>& rs, const std::string& seq, const std::string& config)
{
	for (const auto& r : rs)
		if (r.sequence == seq && r.config == config) return &r;
	return nullptr;
}

/// The run's trajectory, or a text for the cell when there is no number to show.
const TrajectoryResult* trajectoryOf(const RunResult* r, const std::string& name, std::string& why)
{
	why = !r || r->status == RunStatus::Missing ? "not run" : "failed";
	if (!r || r->status == RunStatus::Missing) return nullptr;
	for (const auto& t : r->trajectories)
		if (t.name == name) return t.error.empty() ? &t : nullptr;
	if (r->status == RunStatus::Ok) why = "–";  // this configuration does not write that trajectory here
	return nullptr;
}

struct TableSpec
{
	const char* head;  ///< first column's title
	bool align_column;
	const char* mean_format;  ///< printf format of the two averaged numbers
};

/// One table: a row per (configuration, trajectory), a column per sequence and their mean. `cell`
/// gives the text and the two numbers that the mean averages (NaN: no mean for the row).
using Cell = std::string (*)(const RunResult* r, const std::string& trajectory, double* mean_terms);

void table(std::ostringstream& o, const Plan& plan, const std::vector<RunResult>& rs, const std::vector<Row>& rows,
	const TableSpec& spec, Cell cell)
{
	const bool mean = plan.sequences.size() > 1;
	o << "| " << spec.head << " |" << (spec.align_column ? " align |" : "");
	for (const auto& s : plan.sequences) o << " " << s.name << " |";
	o << (mean ? " mean |\n|---|" : "\n|---|") << (spec.align_column ? "---|" : "");
	for (std::size_t i = 0; i < plan.sequences.size() + (mean ? 1 : 0); ++i) o << "---:|";
	o << "\n";
	for (const auto& row : rows)
	{
		o << "| " << row.config << (row.trajectory.empty() ? "" : " / " + row.trajectory) << " |";
		for (const auto& c : plan.configs)
			if (c.name == row.config && spec.align_column) o << " " << c.align << " |";
		double sum[2] = {0, 0};
		for (const auto& s : plan.sequences)
		{
			double v[2] = {NAN, NAN};
			o << " " << cell(findRun(rs, s.name, row.config), row.trajectory, v) << " |";
			sum[0] += v[0], sum[1] += v[1];
		}
		const double n = static_cast<double>(plan.sequences.size());
		if (mean)
			o << " " << (std::isfinite(sum[0] + sum[1]) ? fmt(spec.mean_format, sum[0] / n, sum[1] / n) : "–") << " |";
		o << "\n";
	}
}
/// Visual odometry: ATE / ARE after the configuration's alignment.
std::string voCell(const RunResult* r, const std::string& name, double* v)
{
	std::string why;
	const TrajectoryResult* t = trajectoryOf(r, name, why);
	if (!t) return why;
	v[0] = t->eval.number("ate_rmse_m"), v[1] = t->eval.number("are_rmse_deg");
	return std::isfinite(v[1]) ? fmt("%.3f / %.2f", v[0], v[1]) : fmt("%.3f / n/a", v[0]);
}

/// Odometry: the KITTI metric, else the ATE.
std::string odometryCell(const RunResult* r, const std::string& name, double* v)
{
	std::string why;
	const TrajectoryResult* t = trajectoryOf(r, name, why);
	if (!t) return why;
	v[0] = t->eval.number("kitti_t_err_pct"), v[1] = t->eval.number("kitti_r_err_deg_per_m");
	if (std::isfinite(v[0]) && std::isfinite(v[1])) return fmt("%.2f / %.4f", v[0], v[1]);
	const double ate = t->eval.number("ate_rmse_m");
	return std::isfinite(ate) ? fmt("ATE %.3f m", ate) : std::string("n/a");
}

/// Revisits: the ATE beside the revisit error (translation RMS), or why there is none.
std::string revisitCell(const RunResult* r, const std::string& name, double* v)
{
	std::string why;
	const TrajectoryResult* t = trajectoryOf(r, name, why);
	if (!t) return why;
	v[0] = t->eval.number("ate_rmse_m"), v[1] = t->eval.number("revisit_t_rmse_m");
	const std::string ate = std::isfinite(v[0]) ? fmt("%.3f", v[0]) : "n/a";
	if (std::isfinite(v[1])) return ate + fmt(" / %.3f", v[1]);
	return ate + (t->eval.number("revisit_pairs") == 0 ? " / no revisit" : " / n/a");
}

/// Whether any trajectory's ground truth comes back to a place: the revisit table is shown then.
bool anyRevisit(const std::vector<RunResult>& rs)
{
	for (const auto& r : rs)
		for (const auto& t : r.trajectories)
			if (t.eval.number("revisit_pairs") > 0) return true;
	return false;
}

std::string timingCell(const RunResult* r, const std::string&, double* v)
{
	if (!r || r->status == RunStatus::Missing) return "not run";
	if (!std::isfinite(r->ms_per_frame)) return "failed";
	v[0] = r->ms_per_frame, v[1] = 0;
	return fmt("%.1f", r->ms_per_frame);
}
}  // namespace

bool isVisualOdometry(const std::string& trajectory) { return trajectory == "vo"; }

std::string markdownResults(
	const Plan& plan, const std::vector<RunResult>& rs, const std::vector<std::string>& snapshots)
{
	std::vector<Row> voRows, odoRows;
	for (const auto& c : plan.configs)
	{
		std::set<std::string, bool (*)(const std::string&, const std::string&)> names(trajectoryBefore);
		for (const auto& r : rs)
			if (r.config == c.name)
				for (const auto& t : r.trajectories) names.insert(t.name);
		if (names.empty()) odoRows.push_back({c.name, ""});
		for (const auto& n : names) (isVisualOdometry(n) ? voRows : odoRows).push_back({c.name, n});
	}
	std::size_t ok = 0, failed = 0, missing = 0;
	for (const auto& r : rs) (r.status == RunStatus::Ok ? ok : r.status == RunStatus::Failed ? failed
																							 : missing)++;

	std::ostringstream o;
	o << "# vlo-batch results\n\nPlan `" << plan.source << "` (resolved copy: `plan.ini`), data in `" << plan.data_dir
	  << "`.\nSequences: " << plan.sequences.size() << ", configurations: " << plan.configs.size()
	  << ", runs: " << rs.size() << " (" << ok << " done, " << failed << " failed, " << missing << " not run).\n";
	if (!voRows.empty())
	{
		o << "\n## Visual odometry: ATE / ARE\n\nATE RMSE [m] / ARE RMSE [deg] after aligning the estimate to the ground "
			 "truth (column align: vlo-eval --align).\n\n";
		table(o, plan, rs, voRows, {"configuration / trajectory", true, "%.3f / %.2f"}, voCell);
	}
	o << "\n## Odometry: KITTI t_err / r_err\n\nKITTI odometry metric, t_err [%] / r_err [deg/m], over segments of "
	  << (plan.kitti_lengths.empty() ? "100, 200, ..., 800" : plan.kitti_lengths)
	  << " m. \"ATE x m\": the ATE RMSE (SE(3)-aligned unless the configuration says otherwise) where the KITTI metric "
		 "is not available (translation-only ground truth, or a drive shorter than the shortest segment).\n\n";
	table(o, plan, rs, odoRows, {"configuration / trajectory", false, "%.2f / %.4f"}, odometryCell);
	if (anyRevisit(rs))
	{
		o << "\n## Revisits: ATE / revisit error\n\nATE RMSE [m] after the configuration's alignment / revisit error RMS [m]: the estimated relative "
			 "pose between two visits of a place against the truth's (doc/EVALUATION.md section 6; places within "
		  << (plan.revisit_radius ? numberWord(*plan.revisit_radius) : "3") << " m after at least "
		  << (plan.revisit_min_path ? numberWord(*plan.revisit_min_path) : "50")
		  << " m of path). \"no revisit\": that drive never comes back to a place. `" << kLoopClosedTrajectory
		  << "`: the loop-closed trajectory (trajectory_" << kLoopClosedTrajectory << ".tum), beside the odometry's.\n\n";
		table(o, plan, rs, odoRows, {"configuration / trajectory", false, "%.3f / %.3f"}, revisitCell);
	}
	o << "\n## Timing\n\nMilliseconds per frame of vlo-run's frame loop (summary.json), whole run.\n\n";
	std::vector<Row> timeRows;
	for (const auto& c : plan.configs) timeRows.push_back({c.name, ""});
	table(o, plan, rs, timeRows, {"configuration", false, "%.1f"}, timingCell);

	std::ostringstream fails;
	for (const auto& r : rs)
	{
		if (r.status == RunStatus::Failed && r.trajectories.empty())
			fails << "| " << r.sequence << " / " << r.config << " | " << escape(r.error) << " |\n";
		for (const auto& tr : r.trajectories)
			if (!tr.error.empty())
				fails << "| " << r.sequence << " / " << r.config << " (" << tr.name << ") | " << escape(tr.error) << " |\n";
	}
	if (!fails.str().empty())
		o << "\n## Failures\n\nFirst error line of each; the logs are in runs/SEQUENCE/CONFIG/ (vlo-run.err, eval_*.err).\n\n"
		  << "| run | error |\n|---|---|\n"
		  << fails.str();
	std::ostringstream reports;  // each run's own report (vlo-run's report.md), where it wrote one
	for (const auto& r : rs)
		if (std::filesystem::is_regular_file(r.dir + "/report.md"))
			reports << "- [" << r.sequence << " / " << r.config << "](runs/" << r.sequence << "/" << r.config << "/report.md)\n";
	if (!reports.str().empty()) o << "\n## Run reports\n\n"
								  << reports.str();
	if (!snapshots.empty())
	{
		o << "\n## Trajectories\n\nTop-down, every configuration against the ground truth (Sim(3)-aligned where the "
			 "configuration is evaluated so).\n\n";
		for (const auto& s : snapshots) o << "![" << s << "](" << s << ")\n";
	}
	return o.str();
}
}  // namespace vlo::batch
