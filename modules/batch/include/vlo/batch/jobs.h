#pragma once
// The processes of a plan: generating a sequence (vlo-sim) and one sequence x configuration run
// (vlo-run, then vlo-eval on every trajectory_*.tum it leaves). Each job is given twice, as argument
// lists that vlo-batch starts itself and as one self-contained shell line for --emit-jobs; both write
// the same files (names below), which is all that collecting the results reads.
#include <vlo/batch/plan.h>

#include <string>
#include <vector>

namespace vlo::batch
{
/// File names inside a run folder OUT/runs/SEQUENCE/CONFIG.
namespace files
{
constexpr const char* kExitCode = "exit_code";  ///< the job's exit code, written last
constexpr const char* kRunOut = "vlo-run.out";
constexpr const char* kRunErr = "vlo-run.err";
constexpr const char* kSummary = "summary.json";  ///< written by vlo-run
inline std::string trajectory(const std::string& t) { return "trajectory_" + t + ".tum"; }
inline std::string evalJson(const std::string& t) { return "eval_" + t + ".json"; }
inline std::string evalOut(const std::string& t) { return "eval_" + t + ".out"; }
inline std::string evalErr(const std::string& t) { return "eval_" + t + ".err"; }
inline std::string aligned(const std::string& t) { return "aligned_" + t + ".tum"; }  ///< Sim(3) configurations only
}  // namespace files

/// One process: argv[0] is an absolute path; stdout and stderr go to files (relative to the job's folder).
struct Step
{
	std::vector<std::string> argv;
	std::string out, err;
};

struct DataJob
{
	std::string name;  ///< the sequence
	std::string rawlog, gt;  ///< what it makes
	Step sim;  ///< vlo-sim; its logs are absolute: OUT/generate/NAME.{out,err}
	std::string record_path, record;  ///< written after a successful vlo-sim (simRecord)
};

struct RunJob
{
	std::string name;  ///< "SEQUENCE/CONFIG"
	std::string sequence, config;
	std::string dir;  ///< absolute: OUT/runs/SEQUENCE/CONFIG
	Step run;  ///< vlo-run
	std::vector<std::string> eval_args;  ///< vlo-eval up to --est
	bool write_aligned = false;  ///< Sim(3) alignment: keep the aligned estimate for the snapshot

	/// vlo-eval of trajectory_<t>.tum in `dir`.
	Step evalStep(const std::string& t) const;
};

std::string runDir(const std::string& out, const std::string& sequence, const std::string& config);
DataJob dataJob(const Sequence& s, const std::string& bin_dir, const std::string& out);
/// NAME.sim.txt beside a drive vlo-batch generated: its vlo-sim arguments (paths relative to the data
/// folder), so that a plan whose sim line changed does not silently run on the old drive.
std::string simRecordPath(const Sequence& s);
std::string simRecord(const Sequence& s);
/// InputError when the drive exists and its record names other arguments than the plan's sim line. A
/// drive without a record was made elsewhere and is used as it is.
void requireSameSimArgs(const Sequence& s);
RunJob runJob(const Plan& p, const Sequence& s, const Config& c, const std::string& bin_dir, const std::string& out);
/// Every sequence x configuration, sequences outermost (plan order).
std::vector<RunJob> runJobs(const Plan& p, const std::string& bin_dir, const std::string& out);

/// POSIX sh lines. The data line does nothing when the rawlog and ground truth exist; the run line
/// records its exit code in `exit_code` and exits with it.
std::string shellLine(const DataJob& j);
std::string shellLine(const RunJob& j);
}  // namespace vlo::batch
