#pragma once
// The three things vlo-batch does (doc/BATCH.md): run a plan here, write it out as job lists for a
// cluster, and collect the results of finished runs into results.md / results.csv.
#include <string>

namespace vlo::batch
{
struct BatchOptions
{
	std::string plan, out;  ///< the plan file and the output folder
	std::string data;  ///< overrides the plan's [plan] data when not empty
	std::string bin_dir;  ///< where vlo-sim, vlo-run and vlo-eval are (absolute)
	int jobs = 1;  ///< processes at once
	std::string emit_jobs, emit_data;  ///< job-list files to write instead of running
};

/// Generates missing sequences, runs every sequence x configuration, collects the results.
/// Returns 0 when every run succeeded, 1 otherwise (after all of them ran). Throws InputError for a
/// bad plan before anything runs.
int runPlan(const BatchOptions& o);
/// Writes OUT/plan.ini and the job lists (one shell line per job); runs nothing.
void emitJobs(const BatchOptions& o);
/// Tables and snapshots from OUT/plan.ini and OUT/runs/. Returns 0 when every run succeeded, else 1.
int collect(const std::string& out);
}  // namespace vlo::batch
