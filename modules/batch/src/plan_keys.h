#pragma once
// Helpers shared by the plan reader's files: reading one section's values with errors that name the
// plan file, the section and the key.
#include <mrpt/config/CConfigFileMemory.h>

#include <string>
#include <vector>

namespace vlo::batch
{
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
	std::string get(const std::string& key, const std::string& fallback = "") const;
	bool getBool(const std::string& key, bool fallback) const;

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
