#include "plan_keys.h"

#include <vlo/core/error.h>

#include <filesystem>
#include <map>

namespace fs = std::filesystem;

namespace vlo::batch
{
std::string SectionReader::get(const std::string& key, const std::string& fallback) const
{
	return has(key) ? ini_.read_string(section_, key, fallback) : fallback;
}

bool SectionReader::getBool(const std::string& key, bool fallback) const
{
	if (!has(key)) return fallback;
	const std::string v = get(key);
	if (v == "true" || v == "1" || v == "yes") return true;
	if (v == "false" || v == "0" || v == "no") return false;
	failInput(where(key), "expects true or false, got '" + v + "'");
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
		{"foliage-depth", true}, {"blackout", true}};
	const std::string at = r.where("sim");
	for (std::size_t i = 0; i < args.size(); ++i)
	{
		const std::string& a = args[i];
		if (a.rfind("--", 0) != 0) failInput(at, "unexpected word '" + a + "' (expected vlo-sim options)");
		const auto it = kOptions.find(a.substr(2));
		if (it == kOptions.end())
			failInput(at, "'" + a + "' is not allowed (vlo-sim options: --scenario --lidar --frames --seed " +
					"--trajectory --lidar-distortion --no-noise --foliage-depth --blackout; vlo-batch sets --out and --quiet)");
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
