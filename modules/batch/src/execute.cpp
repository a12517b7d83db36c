#include <vlo/batch/execute.h>
#include <vlo/batch/process.h>
#include <vlo/core/error.h>
#include <vlo/core/interrupt.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace vlo::batch
{
namespace
{
bool startsEnds(const std::string& s, const std::string& prefix, const std::string& suffix)
{
	return s.size() >= prefix.size() + suffix.size() && s.rfind(prefix, 0) == 0 &&
		s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// The shell line's "rm -f exit_code summary.json trajectory_*.tum eval_* aligned_*".
void removeEarlierAttempt(const std::string& dir)
{
	for (const auto& e : fs::directory_iterator(dir))
	{
		const std::string n = e.path().filename().string();
		if (n == files::kExitCode || n == files::kSummary || startsEnds(n, "trajectory_", ".tum") ||
			startsEnds(n, "eval_", "") || startsEnds(n, "aligned_", ""))
			fs::remove(e.path());
	}
}

void prepareDir(const std::string& dir)
{
	std::error_code ec;
	fs::create_directories(dir, ec);
	if (ec) failInput(dir, "cannot create the run folder");
	removeEarlierAttempt(dir);
}

int finish(const std::string& dir, int rc)
{
	std::ofstream(dir + "/" + files::kExitCode) << rc << "\n";
	return rc;
}

int runAndEvaluate(const RunJob& j)
{
	prepareDir(j.dir);
	// The steps name their files relative to the run folder, like the shell line after its cd.
	if (chdir(j.dir.c_str()) != 0) failInput(j.dir, "cannot enter the run folder");
	const int rc = runStep(j.run);
	if (rc != 0) return finish(".", rc);
	std::vector<std::string> names;  // trajectory_<name>.tum, sorted like the shell's glob
	for (const auto& e : fs::directory_iterator("."))
	{
		const std::string n = e.path().filename().string();
		if (startsEnds(n, "trajectory_", ".tum")) names.push_back(n.substr(11, n.size() - 15));
	}
	std::sort(names.begin(), names.end());
	int evalRc = 0;
	for (const auto& t : names)
		if (runStep(j.evalStep(t)) != 0) evalRc = 1;
	return finish(".", evalRc);
}
}  // namespace

int executeDataJob(const DataJob& j)
{
	if (fs::is_regular_file(j.rawlog) && fs::is_regular_file(j.gt)) return 0;
	fs::create_directories(fs::path(j.rawlog).parent_path());
	fs::create_directories(fs::path(j.sim.err).parent_path());
	const int rc = runStep(j.sim);
	if (rc == 0) std::ofstream(j.record_path) << j.record << "\n";
	return rc;
}

int executeRunJob(const RunJob& j)
{
	try
	{
		return runAndEvaluate(j);
	}
	catch (const Interrupted&)
	{
		// No half-done run that looks like a failed one: its folder goes (vlo-run has removed its own files),
		// and runs/SEQUENCE/ and runs/ if nothing else is in them.
		std::error_code ec;
		fs::remove_all(j.dir, ec);
		const fs::path sequenceDir = fs::path(j.dir).parent_path();
		if (fs::remove(sequenceDir, ec)) fs::remove(sequenceDir.parent_path(), ec);
		throw;
	}
}

void recordSkippedRun(const RunJob& j, const std::string& why)
{
	prepareDir(j.dir);
	std::ofstream(j.dir + "/" + files::kRunErr) << why << "\n";
	finish(j.dir, 1);
}
}  // namespace vlo::batch
