// vlo-batch: runs an experiment plan (sequences x configurations) and tabulates it (doc/BATCH.md).
#include <vlo/batch/batch.h>
#include <vlo/core/app_main.h>
#include <vlo/core/app_cli.h>
#include <vlo/core/error.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <thread>

int main(int argc, char** argv)
{
	return vlo::runApp("vlo-batch", [&] {
		const vlo::CommandLine cl = vlo::parseAppCommandLine(argc, argv, 1,
			{{"plan", "PLAN.ini", "experiment plan, e.g. ini/experiments/paper-table.ini"},
				{"out", "DIR", "output folder: plan.ini, runs/, results.md, results.csv, snapshots/"},
				{"data", "DIR", "folder of the plan's rawlogs (default: the plan's [plan] data)"},
				{"jobs", "N", "processes at once (default: number of cores)"},
				{"emit-jobs", "FILE", "write one shell line per run to FILE instead of running"},
				{"emit-data", "FILE", "write one shell line per sequence to generate to FILE"},
				{"collect", "DIR", "only build results.md/results.csv/snapshots from DIR's finished runs"},
				{"bin", "DIR", "where vlo-sim, vlo-run and vlo-eval are (default: beside vlo-batch)"}},
			"usage: vlo-batch --plan PLAN.ini --out DIR [--data DIR] [--jobs N]\n"
			"       vlo-batch --plan PLAN.ini --out DIR [--data DIR] --emit-jobs FILE [--emit-data FILE]\n"
			"       vlo-batch --collect DIR\n\n"
			"Runs every sequence of the plan under every configuration (vlo-sim for missing sequences,\n"
			"vlo-run, vlo-eval), or writes them as shell lines for GNU parallel or a Slurm array, and\n"
			"tabulates the results in DIR/results.md and DIR/results.csv. See doc/BATCH.md.");
		if (cl.has("collect"))
		{
			for (const char* o : {"plan", "out", "data", "jobs", "emit-jobs", "emit-data", "bin"})
				if (cl.has(o)) vlo::failInput("command line", std::string("--collect takes no --") + o);
			return vlo::batch::collect(cl.get("collect"));
		}
		if (!cl.has("plan") || !cl.has("out"))
			vlo::failInput("command line", "give --plan and --out, or --collect (see --help)");
		vlo::batch::BatchOptions o;
		o.plan = cl.get("plan");
		o.out = cl.get("out");
		o.data = cl.get("data");
		const long cores = std::max(1u, std::thread::hardware_concurrency());
		const long jobs = cl.getInt("jobs", cores);
		if (jobs < 1 || jobs > 1024) vlo::failInput("--jobs", "must be between 1 and 1024");
		o.jobs = static_cast<int>(jobs);
		const auto self = std::filesystem::read_symlink("/proc/self/exe").parent_path();
		o.bin_dir = std::filesystem::absolute(cl.get("bin", self.string())).lexically_normal().string();
		o.emit_jobs = cl.get("emit-jobs");
		o.emit_data = cl.get("emit-data");
		if (o.emit_jobs.empty() && o.emit_data.empty()) return vlo::batch::runPlan(o);
		if (cl.has("jobs")) vlo::failInput("command line", "--jobs has no effect with --emit-jobs/--emit-data");
		vlo::batch::emitJobs(o);
		return 0;
	});
}
