#pragma once
// Reading back what the jobs left in OUT/runs/SEQUENCE/CONFIG: exit code, summary.json, and one
// vlo-eval JSON per trajectory. Shared by a local run and --collect after a cluster run.
#include <vlo/batch/json_fields.h>
#include <vlo/batch/plan.h>

#include <cmath>
#include <string>
#include <vector>

namespace vlo::batch
{
/// The loop-closed trajectory's name: vlo-run writes trajectory_slam.tum with loop closure on, beside the
/// odometry's own trajectory_<mode>.tum.
constexpr const char* kLoopClosedTrajectory = "slam";
/// The order of a run's trajectories in the tables: by name, the loop-closed one after the odometry's.
bool trajectoryBefore(const std::string& a, const std::string& b);

struct TrajectoryResult
{
	std::string name;  ///< lo, vo, vlo, slam, ... (from trajectory_<name>.tum)
	JsonFields eval;  ///< vlo-eval's JSON (empty when it failed)
	std::string error;  ///< why there are no numbers; empty when evaluated
	std::string aligned;  ///< Sim(3)-aligned estimate (absolute path), when written
};

enum class RunStatus
{
	Ok,
	Failed,
	Missing  ///< not run (yet): no exit_code
};

struct RunResult
{
	std::string sequence, config, align, dir;
	RunStatus status = RunStatus::Missing;
	std::string error;  ///< for Failed/Missing: what went wrong, one line
	double ms_per_frame = NAN;  ///< NaN when unknown
	double frames = NAN;  ///< NaN when unknown
	std::vector<TrajectoryResult> trajectories;  ///< in trajectoryBefore order
};

/// The first line of a log that reports an error ("...error: ..."), else its first non-empty line;
/// "" for an empty or missing file.
std::string firstErrorLine(const std::string& path);

RunResult collectRun(const std::string& dir, const Sequence& s, const Config& c);
/// Every sequence x configuration of the plan, in runJobs order.
std::vector<RunResult> collectResults(const Plan& plan, const std::string& out);
}  // namespace vlo::batch
