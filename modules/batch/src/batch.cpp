#include <vlo/batch/batch.h>
#include <vlo/batch/execute.h>
#include <vlo/batch/process.h>
#include <vlo/batch/results.h>
#include <vlo/batch/snapshots.h>
#include <vlo/batch/tables.h>
#include <vlo/batch/words.h>
#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>
#include <vlo/core/interrupt.h>
#include <vlo/core/log.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

namespace fs = std::filesystem;

namespace vlo::batch
{
namespace
{
void requireTool(const std::string& bin_dir, const std::string& name)
{
	const std::string p = bin_dir + "/" + name;
	if (access(p.c_str(), X_OK) != 0)
		failInput(p, "not found or not executable (build it: cmake --build build --target " + name + ")");
}

template <class T>
const T& named(const std::vector<T>& items, const std::string& name)
{
	return *std::find_if(items.begin(), items.end(), [&](const T& x) { return x.name == name; });
}

bool needsGeneration(const Sequence& s) { return !s.sim.empty() && s.dataMissing(); }

Plan readCheckedPlan(const BatchOptions& o)
{
	Plan plan = readPlan(o.plan, o.data);
	for (const auto& s : plan.sequences) requireSameSimArgs(s);
	return plan;
}

std::string prepareOut(const BatchOptions& o, const Plan& plan)
{
	const std::string out = fs::absolute(o.out).lexically_normal().string();
	std::error_code ec;
	fs::create_directories(out, ec);
	if (ec) failInput(o.out, "cannot create the output folder");
	AtomicOutputFile f(out + "/plan.ini");
	f.stream() << resolvedPlanText(plan);
	f.commit();
	return out;
}

void writeText(const std::string& path, const std::string& text)
{
	AtomicOutputFile f(path);
	f.stream() << text;
	f.commit();
}

/// results.md, results.csv and snapshots; returns the number of runs that did not succeed.
std::size_t writeResults(const Plan& plan, const std::string& out)
{
	const auto results = collectResults(plan, out);
	const auto pngs = writeSnapshots(plan, results, out);
	writeText(out + "/results.md", markdownResults(plan, results, pngs));
	writeText(out + "/results.csv", csvResults(results));
	std::size_t bad = 0;
	for (const auto& r : results)
	{
		bool ok = r.status == RunStatus::Ok;
		for (const auto& t : r.trajectories) ok = ok && t.error.empty();
		bad += ok ? 0 : 1;
	}
	std::printf("vlo-batch: %zu runs, %zu did not succeed -> %s/results.md, results.csv\n", results.size(), bad,
		out.c_str());
	return bad;
}

void report(const char* what, const TaskResult& r, std::size_t done, std::size_t total, const std::string& why)
{
	logger().logFmt(mrpt::system::LVL_INFO, "%s %zu/%zu %s: %s, %.1f s%s%s", what, done, total, r.name.c_str(),
		r.exit_code == 0 ? "ok" : "FAILED", r.seconds, why.empty() ? "" : ": ", why.c_str());
}
std::string joinNames(const std::vector<TaskResult>& results, bool (*pick)(const TaskResult&))
{
	std::string names;
	for (const auto& r : results)
		if (pick(r)) names += (names.empty() ? "" : ", ") + r.name;
	return names;
}

/// After a stage's tasks: if a signal interrupted vlo-batch, says what it stopped (each task has removed
/// what it was writing) and what never started; runApp turns it into exit code 130.
void stopIfInterrupted(const char* stage, const std::vector<TaskResult>& results, const char* removed, const char* rest)
{
	if (interruptSignal() == 0) return;
	const std::string stopped = joinNames(results, [](const TaskResult& r) { return r.stopped; });
	const std::string unstarted = joinNames(results, [](const TaskResult& r) { return !r.started; });
	std::string what = "nothing was running";
	if (!stopped.empty()) what = std::string("stopped ") + stage + ": " + stopped + " (" + removed + ")";
	if (!unstarted.empty()) what += "; not started: " + unstarted;
	throw Interrupted(what + "; " + rest);
}
}  // namespace

int runPlan(const BatchOptions& o)
{
	const Plan plan = readCheckedPlan(o);
	requireTool(o.bin_dir, "vlo-run");
	requireTool(o.bin_dir, "vlo-eval");
	std::vector<Task> gen;
	for (const auto& s : plan.sequences)
		if (needsGeneration(s)) gen.push_back({s.name, {}});
	if (!gen.empty()) requireTool(o.bin_dir, "vlo-sim");
	const std::string out = prepareOut(o, plan);

	// Sequences first (all of them, in parallel), then the runs.
	std::set<std::string> notGenerated;
	for (auto& t : gen)
	{
		const DataJob j = dataJob(named(plan.sequences, t.name), o.bin_dir, out);
		t.body = [j] { return executeDataJob(j); };
	}
	const auto genResults = runTasks(gen, o.jobs, [&](const TaskResult& r, std::size_t done, std::size_t total) {
		const std::string err = out + "/generate/" + r.name + ".err";
		if (r.exit_code != 0) notGenerated.insert(r.name);
		report("generated", r, done, total, r.exit_code ? firstErrorLine(err) + " (" + err + ")" : "");
	});
	stopIfInterrupted("generating", genResults, "vlo-sim removes its partial drive", "no run started");

	std::vector<Task> tasks;
	const auto jobs = runJobs(plan, o.bin_dir, out);
	for (const auto& j : jobs)
		if (notGenerated.count(j.sequence))
			recordSkippedRun(j, "not run: sequence " + j.sequence + " could not be generated (see " + out + "/generate/)");
		else
			tasks.push_back({j.name, [j] { return executeRunJob(j); }});
	const auto runResults = runTasks(tasks, o.jobs, [&](const TaskResult& r, std::size_t done, std::size_t total) {
		const RunJob& j = named(jobs, r.name);
		const std::string why =
			r.exit_code ? collectRun(j.dir, named(plan.sequences, j.sequence), named(plan.configs, j.config)).error : "";
		report("run", r, done, total, why);
	});
	stopIfInterrupted("runs", runResults, "their folders removed", "results.md not written");
	return writeResults(plan, out) == 0 ? 0 : 1;
}

void emitJobs(const BatchOptions& o)
{
	const Plan plan = readCheckedPlan(o);
	std::vector<std::string> missing;
	for (const auto& s : plan.sequences)
		if (needsGeneration(s)) missing.push_back(s.name);
	if (!o.emit_jobs.empty())
	{
		requireTool(o.bin_dir, "vlo-run");
		requireTool(o.bin_dir, "vlo-eval");
	}
	if (!o.emit_data.empty() && !missing.empty()) requireTool(o.bin_dir, "vlo-sim");
	const std::string out = prepareOut(o, plan);
	if (!o.emit_jobs.empty())
	{
		std::string lines;
		for (const auto& j : runJobs(plan, o.bin_dir, out)) lines += shellLine(j) + "\n";
		writeText(o.emit_jobs, lines);
		std::printf("vlo-batch: %zu run jobs -> %s\n", plan.sequences.size() * plan.configs.size(), o.emit_jobs.c_str());
	}
	if (!o.emit_data.empty())
	{
		std::string lines;
		for (const auto& s : plan.sequences)
			if (needsGeneration(s)) lines += shellLine(dataJob(s, o.bin_dir, out)) + "\n";
		writeText(o.emit_data, lines);
		std::printf("vlo-batch: %zu sequences to generate -> %s\n", missing.size(), o.emit_data.c_str());
	}
	else if (!missing.empty())
	{
		std::string names;
		for (const auto& m : missing) names += (names.empty() ? "" : ", ") + m;
		logger().logStr(mrpt::system::LVL_WARN,
			"not generated yet: " + names + "; emit them with --emit-data FILE and run those lines first");
	}
	std::printf("vlo-batch: then: %s --collect %s\n", shellQuote(o.bin_dir + "/vlo-batch").c_str(), shellQuote(out).c_str());
}

int collect(const std::string& outArg)
{
	const std::string out = fs::absolute(outArg).lexically_normal().string();
	const std::string planPath = out + "/plan.ini";
	if (!fs::is_regular_file(planPath))
		failInput(outArg, "no plan.ini (not an output folder of vlo-batch --plan or --emit-jobs)");
	return writeResults(readPlan(planPath, "", false), out) == 0 ? 0 : 1;
}
}  // namespace vlo::batch
