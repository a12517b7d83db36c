#include <vlo/batch/jobs.h>
#include <vlo/batch/results.h>
#include <vlo/core/error.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace vlo::batch
{
std::string firstErrorLine(const std::string& path)
{
	std::ifstream in(path);
	std::string line, first;
	while (std::getline(in, line))
	{
		if (!line.empty() && line.back() == '\r') line.pop_back();
		if (line.find("error:") != std::string::npos) return line;
		if (first.empty()) first = line;
	}
	return first;
}

bool trajectoryBefore(const std::string& a, const std::string& b)
{
	const bool aClosed = a == kLoopClosedTrajectory, bClosed = b == kLoopClosedTrajectory;
	return aClosed != bClosed ? bClosed : a < b;
}

RunResult collectRun(const std::string& dir, const Sequence& s, const Config& c)
{
	RunResult r;
	r.sequence = s.name;
	r.config = c.name;
	r.align = c.align;
	r.dir = dir;
	std::ifstream code(dir + "/" + files::kExitCode);
	int exitCode = 0;
	if (!(code >> exitCode))
	{
		r.error = fs::is_directory(dir) ? "did not finish (no exit_code)" : "not run";
		return r;
	}
	r.status = exitCode == 0 ? RunStatus::Ok : RunStatus::Failed;
	const std::string summary = dir + "/" + files::kSummary;
	if (!fs::is_regular_file(summary))
	{
		// vlo-run failed: its stderr says why.
		r.status = RunStatus::Failed;
		const std::string line = firstErrorLine(dir + "/" + files::kRunErr);
		r.error = line.empty() ? "vlo-run exited with code " + std::to_string(exitCode) : line;
		return r;
	}
	try
	{
		const auto sj = JsonFields::read(summary);
		r.ms_per_frame = sj.number("ms_per_frame");
		r.frames = sj.number("frames");
	}
	catch (const InputError& e)
	{
		// One damaged file must not keep the other runs out of the tables.
		r.status = RunStatus::Failed;
		r.error = e.what();
		return r;
	}
	for (const auto& e : fs::directory_iterator(dir))
	{
		const std::string n = e.path().filename().string();
		if (n.rfind("trajectory_", 0) != 0 || e.path().extension() != ".tum") continue;
		TrajectoryResult t;
		t.name = n.substr(11, n.size() - 15);
		const std::string json = dir + "/" + files::evalJson(t.name);
		if (fs::is_regular_file(json))
		{
			try
			{
				t.eval = JsonFields::read(json);
			}
			catch (const InputError& e)
			{
				t.error = e.what();
			}
		}
		else
		{
			const std::string line = firstErrorLine(dir + "/" + files::evalErr(t.name));
			t.error = line.empty() ? "not evaluated" : line;
		}
		if (fs::is_regular_file(dir + "/" + files::aligned(t.name))) t.aligned = dir + "/" + files::aligned(t.name);
		r.trajectories.push_back(t);
	}
	std::sort(r.trajectories.begin(), r.trajectories.end(),
		[](const TrajectoryResult& a, const TrajectoryResult& b) { return trajectoryBefore(a.name, b.name); });
	if (r.trajectories.empty())
	{
		r.status = RunStatus::Failed;
		r.error = "vlo-run left no trajectory_*.tum";
	}
	else if (r.status == RunStatus::Failed)
		for (const auto& t : r.trajectories)
			if (!t.error.empty() && r.error.empty()) r.error = "trajectory_" + t.name + ".tum: " + t.error;
	return r;
}

std::vector<RunResult> collectResults(const Plan& plan, const std::string& out)
{
	std::vector<RunResult> results;
	for (const auto& s : plan.sequences)
		for (const auto& c : plan.configs) results.push_back(collectRun(runDir(out, s.name, c.name), s, c));
	return results;
}
}  // namespace vlo::batch
