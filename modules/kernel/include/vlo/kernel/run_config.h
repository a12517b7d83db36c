#pragma once
// The INI configuration of a run: the user's file plus "--set section.key=value" overrides.
// Every module loads its options (an OptionSet) through load(); afterwards checkAllKeysUsed() rejects any
// section or key that no module knows, and effectiveIni() holds the values actually used. Every error
// names where the value came from: "--set loam.mapping.map_radius=abc: ..." for an override,
// "run.ini: [loam.mapping] map_radius: ..." for the file.
#include <mrpt/config/CConfigFileMemory.h>
#include <vlo/core/option_table.h>

#include <map>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace vlo::kernel
{
class RunConfig
{
   public:
	/// `origin` names the source in error messages (the INI path). Throws InputError for an unreadable
	/// file or a malformed override.
	static RunConfig fromFile(const std::string& path, const std::vector<std::string>& overrides = {});
	static RunConfig fromString(const std::string& ini, const std::string& origin = "<memory>",
		const std::vector<std::string>& overrides = {});

	/// Loads `opts` from `section` (defaults where absent): types, ranges and relations, in one place.
	void load(OptionSet& opts, const std::string& section);
	/// Throws InputError naming the first section or key that no load() consumed, and the nearest known
	/// one when it looks like a typo.
	void checkAllKeysUsed() const;
	/// The effective values of every loaded section, as an INI text.
	std::string effectiveIni() const { return effective_.getContent(); }

	/// The keys every load() declared, by section: what doc/OPTIONS.md lists.
	const std::map<std::string, std::vector<OptionRow>>& declared() const { return declared_; }

	const mrpt::config::CConfigFileBase& ini() const { return user_; }
	const std::string& origin() const { return origin_; }

	/// "--set section.key=value" when an override gave the key, else "<file>: [section] key": the
	/// prefix of an error about that key's value.
	std::string where(const std::string& section, const std::string& key) const;

   private:
	mrpt::config::CConfigFileMemory user_, effective_;
	std::string origin_;
	std::set<std::pair<std::string, std::string>> known_;
	std::set<std::string> known_sections_;
	std::map<std::pair<std::string, std::string>, std::string> overrides_;
	std::map<std::string, std::vector<OptionRow>> declared_;  ///< (section, key) -> the --set text
};
}  // namespace vlo::kernel
