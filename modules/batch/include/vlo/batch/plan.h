#pragma once
// An experiment plan (doc/BATCH.md): sequences (a rawlog with its ground truth, the base INI of its
// sensor, optionally the vlo-sim arguments that generate it) crossed with configurations (--set
// overrides for vlo-run and the alignment used to evaluate them).
#include <optional>
#include <string>
#include <vector>

namespace vlo::batch
{
struct Sequence
{
	std::string name;
	std::string rawlog, gt, ini;  ///< absolute after readPlan
	std::vector<std::string> sim;  ///< vlo-sim arguments (paths absolute), empty: never generated
	bool gt_translation_only = false;
	std::string kitti_calib;  ///< KITTI calib.txt: KITTI metric in camera 0 (absolute; empty: none)

	bool dataMissing() const;  ///< rawlog or ground truth absent
};

struct Config
{
	std::string name;
	std::vector<std::string> overrides;  ///< "section.key=value" for vlo-run --set
	std::string align = "se3";  ///< se3 | sim3 | none, for vlo-eval --align
	std::string ini;  ///< replaces the sequences' base INI when not empty (absolute after readPlan)
};

struct Plan
{
	std::string source;  ///< the plan file as given (also kept in a resolved copy)
	std::string data_dir;  ///< absolute
	std::string kitti_lengths;  ///< for vlo-eval --kitti-lengths; empty: vlo-eval's default
	int kitti_step = 0;  ///< for vlo-eval --kitti-step; 0: vlo-eval's default
	/// For vlo-eval --revisit-radius / --revisit-min-path (m); empty: vlo-eval's default.
	std::optional<double> revisit_radius, revisit_min_path;
	std::vector<Sequence> sequences;  ///< in file order
	std::vector<Config> configs;  ///< in file order
};

/// Reads and checks a plan. `data_dir` overrides [plan] data when not empty. Throws InputError naming
/// the plan file, the section and the key for anything wrong, including a missing INI or rawlog that
/// cannot be generated. Relative paths: ini against the plan's folder, data files against the data dir.
/// `check_files` = false skips the checks that files exist (collecting results needs none of them).
Plan readPlan(const std::string& path, const std::string& data_dir = "", bool check_files = true);
/// The same from text; `plan_dir` resolves ini paths, `origin` names the plan in errors.
Plan parsePlan(const std::string& text, const std::string& origin, const std::string& plan_dir,
	const std::string& data_dir = "", bool check_files = true);

/// A plan file with every path absolute, readable by readPlan from anywhere (written into the output
/// folder so that --collect and the emitted jobs do not depend on the current directory).
std::string resolvedPlanText(const Plan& plan);
}  // namespace vlo::batch
