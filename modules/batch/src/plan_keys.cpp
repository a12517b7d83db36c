#include "plan_keys.h"

#include <vlo/core/error.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace fs = std::filesystem;

namespace vlo::batch
{
void PlanKeys::declare(OptionTable& t)
{
	t.add("data", data, "any", "folder of the sequences' rawlogs, relative to the working folder");
	t.add("kitti_lengths", kitti_lengths, "any", "comma-separated segment lengths [m] of the KITTI metric");
	t.add("kitti_step", kitti_step, "[1, 1000000]", "frames between KITTI metric segment starts");
	t.add("revisit_radius", revisit_radius, "(0, 1000]", "revisit error: positions this close are one place [m]");
	t.add("revisit_min_path", revisit_min_path, "[0, 1000000]", "revisit error: path between two visits [m]");
	t.add("source", source, "any", "what the tables name as the plan's source");
}

void SequenceKeys::declare(OptionTable& t)
{
	t.add("rawlog", rawlog, "any", "the recording (default NAME.rawlog in the data folder)");
	t.add("gt", gt, "any", "ground truth TUM file (default beside the rawlog)");
	t.add("ini", ini, "any", "the sensor's base INI, relative to the plan");
	t.add("sim", sim, "any", "vlo-sim arguments that generate the rawlog when it is missing");
	t.add("gt_translation_only", gt_translation_only, "true | false", "the ground truth has no orientation");
	t.add("kitti_calib", kitti_calib, "any", "KITTI calib.txt for the camera-frame metric");
}

void ConfigKeys::declare(OptionTable& t)
{
	t.add("set", set, "any", "vlo-run --set overrides, section.key=value separated by spaces");
	t.add("align", align, "se3 | sim3 | none", "trajectory alignment of the evaluation");
	t.add("ini", ini, "any", "an INI that replaces the sequence's, relative to the plan");
}

void SectionReader::load(OptionSet& keys) const
{
	std::vector<std::string> known, given;
	for (const auto& row : keys.rows()) known.push_back(row.key);
	ini_.getAllKeys(section_, given);
	for (const auto& k : given)
		if (std::find(known.begin(), known.end(), k) == known.end())
			failInput(origin_ + ": [" + section_ + "]", "unknown key '" + k + "'" + didYouMean(k, known) + " (see doc/BATCH.md)");
	try
	{
		keys.loadFromConfigFile(ini_, section_);
	}
	catch (const OptionError& e)
	{
		failInput(where(e.key()), e.problem());
	}
}

std::string absolutePath(const std::string& p, const std::string& base)
{
	const fs::path path(p);
	return (path.is_absolute() ? path : fs::absolute(fs::path(base) / path)).lexically_normal().string();
}

std::vector<std::string> checkSimArgs(
	std::vector<std::string> args, const std::string& data_dir, bool needed, const SectionReader& r)
{
	// vlo-sim's options (apps/vlo-sim.cpp): true = takes a value. --out and --quiet are vlo-batch's.
	static const std::map<std::string, bool> kOptions{{"scenario", true}, {"lidar", true}, {"frames", true},
		{"seed", true}, {"trajectory", true}, {"lidar-distortion", false}, {"no-noise", false},
		{"foliage-depth", true}, {"blackout", true}, {"realism", false}, {"no-realism", false}, {"point-times", false}};
	const std::string at = r.where("sim");
	for (std::size_t i = 0; i < args.size(); ++i)
	{
		const std::string& a = args[i];
		if (a.rfind("--", 0) != 0) failInput(at, "unexpected word '" + a + "' (expected vlo-sim options)");
		const auto it = kOptions.find(a.substr(2));
		if (it == kOptions.end())
			failInput(at,
				"'" + a + "' is not allowed (vlo-sim options: --scenario --lidar --frames --seed " +
					"--trajectory --lidar-distortion --no-noise --foliage-depth --blackout --realism --no-realism --point-times; "
					"vlo-batch sets --out and --quiet)");
		if (!it->second) continue;
		if (++i >= args.size()) failInput(at, "'" + a + "' needs a value");
		if (a == "--trajectory")
		{
			args[i] = absolutePath(args[i], data_dir);
			if (needed && !fs::is_regular_file(args[i]))
				failInput(at, "--trajectory " + args[i] + " does not exist (KITTI poses: see doc/BATCH.md to unpack them)");
		}
	}
	return args;
}
}  // namespace vlo::batch
