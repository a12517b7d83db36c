#pragma once
// The keys of a plan's sections, declared as every module's options are (vlo/core/option_table.h), and
// a reader of one section whose errors name the plan file, the section and the key.
#include <mrpt/config/CConfigFileMemory.h>
#include <vlo/core/option_table.h>

#include <string>
#include <vector>

namespace vlo::batch
{
/// [plan]
struct PlanKeys : public OptionSet
{
	std::string data = "rawlogs/experiments", kitti_lengths, source;
	int kitti_step = 0;
	double revisit_radius = 3, revisit_min_path = 50;  ///< vlo-eval's defaults

   protected:
	void declare(OptionTable& t) override;
};

/// [sequence NAME]
struct SequenceKeys : public OptionSet
{
	std::string rawlog, gt, ini, sim, kitti_calib;
	bool gt_translation_only = false;

   protected:
	void declare(OptionTable& t) override;
};

/// [config NAME]
struct ConfigKeys : public OptionSet
{
	std::string set, align = "se3", ini;

   protected:
	void declare(OptionTable& t) override;
};

class SectionReader
{
   public:
	SectionReader(const mrpt::config::CConfigFileMemory& ini, std::string origin, std::string section)
		: ini_(ini), origin_(std::move(origin)), section_(std::move(section))
	{
	}
	/// "plan.ini: [sequence a] key", the prefix of every error about that key.
	std::string where(const std::string& key) const { return origin_ + ": [" + section_ + "] " + key; }
	bool has(const std::string& key) const { return ini_.keyExists(section_, key); }
	/// Refuses a key that `keys` does not declare (suggesting the nearest), then loads them.
	void load(OptionSet& keys) const;

   private:
	const mrpt::config::CConfigFileMemory& ini_;
	std::string origin_, section_;
};

/// `p` made absolute against `base` (unless already absolute), normalised.
std::string absolutePath(const std::string& p, const std::string& base);

/// Checks vlo-sim arguments of a plan and makes the --trajectory path absolute against `data_dir`.
/// `needed`: the sequence must be generated now, so the trajectory file must exist.
std::vector<std::string> checkSimArgs(
	std::vector<std::string> args, const std::string& data_dir, bool needed, const SectionReader& r);
}  // namespace vlo::batch
