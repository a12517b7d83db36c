#include <vlo/core/error.h>
#include <vlo/core/ini_text.h>
#include <vlo/core/input_file.h>
#include <vlo/core/option_table.h>
#include <vlo/kernel/run_config.h>

#include <fstream>
#include <sstream>

namespace vlo::kernel
{
namespace
{
/// A file the user gives as an INI must look like one (scanIniText: text, every line a comment, a [section],
/// a key = value inside a section, or an MRPT @directive; nothing given twice), and have a section.
void checkIniSyntax(const std::string& text, const std::string& path)
{
	if (scanIniText(text, path).empty())
		failInput(path, "no [section] in the file: is this an INI file? (see ini/ for examples)");
}
}  // namespace

RunConfig RunConfig::fromFile(const std::string& path, const std::vector<std::string>& overrides)
{
	requireInputFile(path);
	std::ifstream in(path);
	if (!in) failInput(path, "cannot open INI file");
	std::stringstream ss;
	ss << in.rdbuf();
	checkIniSyntax(ss.str(), path);
	try
	{
		return fromString(ss.str(), path, overrides);
	}
	catch (const InputError&)
	{
		throw;
	}
	catch (const std::exception& e)  // MRPT's own parser (e.g. an unclosed ${...}) names no file
	{
		std::string msg = e.what();
		msg = msg.substr(0, msg.find('\n'));
		failInput(path, "not a valid INI file: " + msg);
	}
}

RunConfig RunConfig::fromString(const std::string& ini, const std::string& origin, const std::vector<std::string>& overrides)
{
	RunConfig cfg;
	cfg.origin_ = origin;
	cfg.user_.setContent(ini);
	for (const auto& o : overrides)
	{
		const auto dot = o.find('.'), eq = o.find('=');
		if (dot == std::string::npos || eq == std::string::npos || dot > eq)
			failInput("--set " + o, "expected section.key=value");
		// Sections may contain dots ("loam.odometry"): the key is after the last dot before '='.
		const auto lastDot = o.rfind('.', eq);
		const std::string section = o.substr(0, lastDot), key = trimmed(o.substr(lastDot + 1, eq - lastDot - 1));
		cfg.user_.write(section, key, o.substr(eq + 1));
		cfg.overrides_[{section, key}] = o;
	}
	return cfg;
}

std::string RunConfig::where(const std::string& section, const std::string& key) const
{
	const auto set = overrides_.find({section, key});
	if (set != overrides_.end()) return "--set " + set->second;
	return origin_ + ": [" + printable(section) + "] " + printable(key);
}

void RunConfig::load(OptionSet& opts, const std::string& section)
{
	try
	{
		opts.loadFromConfigFile(user_, section);
	}
	catch (const OptionError& e)
	{
		failInput(where(section, e.key()), e.problem());
	}
	known_sections_.insert(section);
	declared_[section] = opts.rows();
	for (const auto& row : declared_[section]) known_.insert({section, row.key});
	opts.saveToConfigFile(effective_, section);  // with the help text as a comment on each key
}

void RunConfig::checkAllKeysUsed() const
{
	std::vector<std::string> sections;
	user_.getAllSections(sections);
	const std::vector<std::string> knownSections(known_sections_.begin(), known_sections_.end());
	for (const auto& s : sections)
	{
		if (s.empty()) continue;  // @define lines live outside any section
		std::vector<std::string> keys;
		user_.getAllKeys(s, keys);
		if (!known_sections_.count(s))
		{
			// A section that only --set names is blamed on that --set.
			const std::string at = !keys.empty() && overrides_.count({s, trimmed(keys[0])}) ? where(s, trimmed(keys[0])) : origin_;
			failInput(at, "unknown section [" + printable(s) + "]" + didYouMean(s, knownSections));
		}
		std::vector<std::string> knownKeys;
		for (const auto& [section, key] : known_)
			if (section == s) knownKeys.push_back(key);
		for (const auto& padded : keys)
		{
			const std::string k = trimmed(padded);
			if (known_.count({s, k})) continue;
			const std::string at = overrides_.count({s, k}) ? where(s, k) : origin_;
			failInput(at, "unknown key '" + printable(k) + "' in section [" + printable(s) + "]" + didYouMean(k, knownKeys));
		}
	}
}
}  // namespace vlo::kernel
