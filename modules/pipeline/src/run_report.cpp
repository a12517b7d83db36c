#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>
#include <vlo/core/log.h>
#include <vlo/eval/report.h>
#include <vlo/pipeline/run_folder.h>
#include <vlo/pipeline/run_report.h>
#include <vlo/viz/eval_plots.h>
#include <vlo/viz/stage_time_plot.h>

#include <filesystem>
#include <sstream>

namespace vlo::pipeline
{
namespace
{

/// Relative paths of the files where a run writes, sorted.
std::vector<std::string> filesIn(const std::string& dir)
{
	const auto files = filesWhereRunsWrite(dir);
	return {files.begin(), files.end()};
}

bool has(const std::vector<std::string>& files, const std::string& f)
{
	return std::find(files.begin(), files.end(), f) != files.end();
}

std::string fixed(double v, int decimals)
{
	std::ostringstream o;
	o.setf(std::ios::fixed);
	o.precision(decimals);
	o << v;
	return o.str();
}

/// The evaluation as the report shows it: vlo-eval's table in a code block, or why there is none.
std::string accuracyText(const std::string& dir, const RunSummary& s, const RunRequest& req, bool plots)
{
	const std::string traj = dir + "/" + s.final_trajectory;
	if (req.gt.empty() || !std::filesystem::exists(traj)) return {};
	eval::EvalOptions o;
	o.gt_name = req.gt;
	o.est_name = s.final_trajectory;
	o.align = s.mode == "vo" ? eval::Alignment::Sim3 : eval::Alignment::SE3;  // the VO alone is unscaled
	try
	{
		const eval::EvalReport r = evaluate(io::readTum(req.gt), io::readTum(traj), o);
		if (plots) viz::writeEvalPlots(dir + "/snapshots", {{s.mode, r}});
		return "```\n" + eval::formatTable(r) + "```\n";
	}
	catch (const std::exception& e)  // e.g. a ground truth of another drive: the run itself is fine
	{
		return std::string("Not evaluated: ") + e.what() + "\n";
	}
}
}  // namespace

void writeStageTimePlot(const std::string& png, const kernel::FrameTable& table)
{
	std::vector<viz::StageTimeColumn> columns;
	for (const auto& c : table.columns())
		if (c.rfind("ms_", 0) == 0) columns.push_back({c, table.numbers(c)});
	writeStageTimePlot(png, table.numbers("frame"), columns);
}

std::string runReportMarkdown(const RunSummary& s, const RunRequest& req, const std::vector<std::string>& files,
	const std::string& accuracy)
{
	std::ostringstream o;
	o << "# vlo-run report: mode " << s.mode << ", " << s.frames << " frames\n\n";
	o << "| | |\n|---|---|\n";
	o << "| rawlog | `" << req.rawlog << "` |\n| ini | `" << req.ini << "` |\n";
	if (!req.gt.empty()) o << "| ground truth | `" << req.gt << "` |\n";
	o << "| frames | " << s.frames << " |\n";
	if (!s.complete) o << "| complete | **no**: stopped after frame " << s.last_frame << ": " << s.stop_reason << " |\n";
	o << "| time | " << fixed(s.seconds, 1) << " s, " << fixed(s.ms_per_frame, 1) << " ms per frame |\n";
	o << "| path length | " << fixed(s.path_length_m, 1) << " m |\n";
	o << "| largest step | " << fixed(s.max_step_m, 3) << " m |\n";
	if (has(files, s.final_trajectory))
		o << "| trajectory | [" << s.final_trajectory << "](" << s.final_trajectory << ") |\n";
	if (!s.slam_trajectory.empty() && has(files, s.slam_trajectory))
		o << "| loop-closed trajectory | [" << s.slam_trajectory << "](" << s.slam_trajectory << ") |\n";
	for (const auto& [key, value] : s.figures) o << "| " << key << " | " << value << " |\n";
	for (const char* f : {"summary.json", "frames.csv", "run.ini", "map.pcd"})
		if (has(files, f)) o << "| " << f << " | [" << f << "](" << f << ") |\n";
	if (!req.gt.empty()) o << "\n## Accuracy against the ground truth\n\n"
						   << accuracy;
	if (!s.stage_timings.empty())
	{
		o << "\n## Time per stage\n\n";
		if (has(files, "snapshots/time_per_stage.png")) o << "![time per stage](snapshots/time_per_stage.png)\n\n";
		o << "| stage | mean ms | p95 ms | max ms | frames |\n|---|---:|---:|---:|---:|\n";
		for (const auto& t : s.stage_timings)
			o << "| " << t.stage << " | " << fixed(t.mean, 2) << " | " << fixed(t.p95, 2) << " | " << fixed(t.max, 2)
			  << " | " << t.count << " |\n";
	}
	bool heading = false;
	for (const auto& f : files)
	{
		if (f.rfind("snapshots/", 0) != 0 || f.size() < 4 || f.compare(f.size() - 4, 4, ".png") != 0 ||
			f == "snapshots/time_per_stage.png")
			continue;
		if (!heading) o << "\n## Snapshots and plots\n";
		heading = true;
		const std::string name = f.substr(10, f.size() - 14);
		o << "\n### " << name << "\n\n![" << name << "](" << f << ")\n";
	}
	return o.str();
}

void writeRunReport(const std::string& dir, const RunSummary& s, const RunRequest& req, const kernel::FrameTable& table, bool plots)
{
	const std::string accuracy = accuracyText(dir, s, req, plots);
	if (plots)
	{
		try
		{
			std::filesystem::create_directories(dir + "/snapshots");
			writeStageTimePlot(dir + "/snapshots/time_per_stage.png", table);
		}
		catch (const std::exception& e)  // like the snapshots, a convenience: reported, not fatal
		{
			logger().logStr(mrpt::system::LVL_WARN, std::string("time-per-stage plot not written: ") + e.what());
		}
	}
	AtomicOutputFile f(dir + "/report.md");
	f.stream() << runReportMarkdown(s, req, filesIn(dir), accuracy);
	f.commit();
}
}  // namespace vlo::pipeline
