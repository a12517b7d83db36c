#pragma once
// The INI configuration of a run: the user's file plus "--set section.key=value" overrides.
// Every module loads its CLoadableOptions through load(); afterwards checkAllKeysUsed() rejects any
// section or key that no module knows, and effectiveIni() holds the values actually used.
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/config/CLoadableOptions.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace vlo
{
class RunConfig
{
   public:
	/// `origin` names the source in error messages (the INI path). Throws InputError for an unreadable
	/// file or a malformed override.
	static RunConfig fromFile(const std::string& path, const std::vector<std::string>& overrides = {});
	static RunConfig fromString(const std::string& ini, const std::string& origin = "<memory>",
		const std::vector<std::string>& overrides = {});

	/// Gives `section.key` the value `value` unless the file or an override sets it: a default that
	/// depends on another option (e.g. the LOAM prior source in mode vlo).
	void setDefault(const std::string& section, const std::string& key, const std::string& value);
	/// Loads `opts` from `section` (defaults where absent) and validates the types of given values.
	void load(mrpt::config::CLoadableOptions& opts, const std::string& section);
	/// Throws InputError naming the first section or key that no load() consumed.
	void checkAllKeysUsed() const;
	/// The effective values of every loaded section, as an INI text.
	std::string effectiveIni() const { return effective_.getContent(); }

	const mrpt::config::CConfigFileBase& ini() const { return user_; }
	const std::string& origin() const { return origin_; }

   private:
	mrpt::config::CConfigFileMemory user_, effective_;
	std::string origin_;
	std::set<std::pair<std::string, std::string>> known_;
	std::set<std::string> known_sections_;
};
}  // namespace vlo
