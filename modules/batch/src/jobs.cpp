#include <vlo/batch/jobs.h>
#include <vlo/batch/words.h>

#include <vlo/core/error.h>

#include <filesystem>
#include <fstream>

namespace vlo::batch
{
std::string runDir(const std::string& out, const std::string& sequence, const std::string& config)
{
	return out + "/runs/" + sequence + "/" + config;
}

DataJob dataJob(const Sequence& s, const std::string& bin_dir, const std::string& out)
{
	DataJob j;
	j.name = s.name;
	j.rawlog = s.rawlog;
	j.gt = s.gt;
	j.sim.argv = {bin_dir + "/vlo-sim"};
	j.sim.argv.insert(j.sim.argv.end(), s.sim.begin(), s.sim.end());
	for (const char* a : {"--out", s.rawlog.c_str(), "--quiet"}) j.sim.argv.push_back(a);
	j.sim.out = out + "/generate/" + s.name + ".out";
	j.sim.err = out + "/generate/" + s.name + ".err";
	j.record_path = simRecordPath(s);
	j.record = simRecord(s);
	return j;
}

std::string simRecordPath(const Sequence& s)
{
	const std::filesystem::path r(s.rawlog);
	return (r.parent_path() / (r.stem().string() + ".sim.txt")).string();
}

std::string simRecord(const Sequence& s)
{
	const std::filesystem::path data = std::filesystem::path(s.rawlog).parent_path();
	std::vector<std::string> args = s.sim;
	for (std::size_t i = 0; i + 1 < args.size(); ++i)
		if (args[i] == "--trajectory") args[i + 1] = std::filesystem::path(args[i + 1]).lexically_relative(data).string();
	return shellJoin(args);
}

void requireSameSimArgs(const Sequence& s)
{
	if (s.sim.empty() || s.dataMissing()) return;
	std::ifstream in(simRecordPath(s));
	if (!in) return;
	std::string recorded;
	std::getline(in, recorded);
	if (recorded != simRecord(s))
		failInput(s.rawlog,
			"was generated with vlo-sim " + recorded + " but the plan's sim line says " + simRecord(s) +
				": delete the drive (.rawlog, .gt.tum, _Images/, .sim.txt) to generate it again");
}

RunJob runJob(const Plan& p, const Sequence& s, const Config& c, const std::string& bin_dir, const std::string& out)
{
	RunJob j;
	j.sequence = s.name;
	j.config = c.name;
	j.name = s.name + "/" + c.name;
	j.dir = runDir(out, s.name, c.name);
	const std::string ini = c.ini.empty() ? s.ini : c.ini;
	j.run.argv = {bin_dir + "/vlo-run", "--rawlog", s.rawlog, "--ini", ini, "--out", j.dir, "--gt", s.gt, "--quiet",
		"--overwrite"};  // a run folder is the plan's: a rerun replaces its earlier attempt
	for (const auto& o : c.overrides)
	{
		j.run.argv.push_back("--set");
		j.run.argv.push_back(o);
	}
	j.run.out = files::kRunOut;
	j.run.err = files::kRunErr;
	j.eval_args = {bin_dir + "/vlo-eval", "--gt", s.gt, "--metric", "all", "--align", c.align};
	if (!p.kitti_lengths.empty()) j.eval_args.insert(j.eval_args.end(), {"--kitti-lengths", p.kitti_lengths});
	if (p.kitti_step > 0) j.eval_args.insert(j.eval_args.end(), {"--kitti-step", std::to_string(p.kitti_step)});
	if (p.revisit_radius) j.eval_args.insert(j.eval_args.end(), {"--revisit-radius", numberWord(*p.revisit_radius)});
	if (p.revisit_min_path) j.eval_args.insert(j.eval_args.end(), {"--revisit-min-path", numberWord(*p.revisit_min_path)});
	if (s.gt_translation_only) j.eval_args.push_back("--gt-translation-only");
	if (!s.kitti_calib.empty()) j.eval_args.insert(j.eval_args.end(), {"--kitti-calib", s.kitti_calib});
	j.write_aligned = c.align == "sim3";
	return j;
}

std::vector<RunJob> runJobs(const Plan& p, const std::string& bin_dir, const std::string& out)
{
	std::vector<RunJob> jobs;
	for (const auto& s : p.sequences)
		for (const auto& c : p.configs) jobs.push_back(runJob(p, s, c, bin_dir, out));
	return jobs;
}

Step RunJob::evalStep(const std::string& t) const
{
	Step e{eval_args, files::evalOut(t), files::evalErr(t)};
	e.argv.insert(e.argv.end(), {"--est", files::trajectory(t), "--json", files::evalJson(t)});
	if (write_aligned) e.argv.insert(e.argv.end(), {"--write-aligned", files::aligned(t)});
	return e;
}

std::string shellLine(const DataJob& j)
{
	const std::string dataDir = std::filesystem::path(j.rawlog).parent_path().string();
	const std::string logDir = std::filesystem::path(j.sim.err).parent_path().string();
	return "[ -s " + shellQuote(j.rawlog) + " ] && [ -s " + shellQuote(j.gt) + " ] || { mkdir -p " +
		shellQuote(dataDir) + " " + shellQuote(logDir) + " && " + shellJoin(j.sim.argv) + " > " + shellQuote(j.sim.out) +
		" 2> " + shellQuote(j.sim.err) + " && printf '%s\\n' " + shellQuote(j.record) + " > " + shellQuote(j.record_path) + "; }";
}

std::string shellLine(const RunJob& j)
{
	// Files of an earlier attempt go first, so that a failed rerun cannot look like a success.
	// Inside the loop $t is the trajectory's name (lo, vo, vlo, ...); the file names match files::.
	std::string eval = shellJoin(j.eval_args) + " --est \"trajectory_$t.tum\" --json \"eval_$t.json\"";
	if (j.write_aligned) eval += " --write-aligned \"aligned_$t.tum\"";
	eval += " > \"eval_$t.out\" 2> \"eval_$t.err\"";
	return "mkdir -p " + shellQuote(j.dir) + " && cd " + shellQuote(j.dir) +
		" || exit 1; rm -f exit_code summary.json trajectory_*.tum eval_* aligned_*; ( " + shellJoin(j.run.argv) + " > " +
		j.run.out + " 2> " + j.run.err +
		" || exit $?; rc=0; for f in trajectory_*.tum; do [ -e \"$f\" ] || continue; "
		"t=${f#trajectory_}; t=${t%.tum}; " +
		eval +
		" || rc=1; done; exit $rc ); rc=$?; echo $rc > exit_code; exit $rc";
}
}  // namespace vlo::batch
