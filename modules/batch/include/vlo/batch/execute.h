#pragma once
// What vlo-batch does for one job when it runs a plan itself: the same processes and files as the
// job's shell line (jobs.h), without a shell. executeRunJob changes the current folder: call it in a
// child process.
#include <vlo/batch/jobs.h>

namespace vlo::batch
{
/// Generates the sequence unless its rawlog and ground truth exist; returns vlo-sim's exit code.
int executeDataJob(const DataJob& j);
/// vlo-run, then vlo-eval on every trajectory_*.tum; writes exit_code; returns it. Interrupted, it
/// removes the run folder and throws Interrupted.
int executeRunJob(const RunJob& j);
/// A run that cannot happen (its sequence was not generated): leaves `why` as vlo-run.err and exit code 1.
void recordSkippedRun(const RunJob& j, const std::string& why);
}  // namespace vlo::batch
