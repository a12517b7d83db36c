#pragma once
// results.md (the paper's tables: visual odometry by ATE/ARE, odometry by the KITTI metric, timing)
// and results.csv (one row per sequence x configuration x trajectory, every number) from collected runs.
#include <vlo/batch/plan.h>
#include <vlo/batch/results.h>

#include <string>
#include <vector>

namespace vlo::batch
{
/// Trajectories named "vo" go to the visual-odometry table, all others (lo, vlo, ...) to the odometry table.
bool isVisualOdometry(const std::string& trajectory);

/// `snapshots`: PNG paths relative to the output folder, one per sequence that has one.
std::string markdownResults(
	const Plan& plan, const std::vector<RunResult>& results, const std::vector<std::string>& snapshots);
std::string csvResults(const std::vector<RunResult>& results);
}  // namespace vlo::batch
