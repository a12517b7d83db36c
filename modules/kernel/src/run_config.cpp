#include <vlo/core/error.h>
#include <vlo/core/option_table.h>
#include <vlo/kernel/run_config.h>

#include <fstream>
#include <sstream>

namespace vlo
{
namespace
{
/// A file the user gives as an INI must look like one: text, every line a comment, a [section], a
/// key = value inside a section, or an MRPT @directive; and at least one section.
void checkIniSyntax(const std::string& text, const std::string& path)
{
	if (text.find('\0') != std::string::npos) failInput(path, "not an INI file (binary content)");
	std::istringstream in(text);
	std::string line;
	bool section = false;
	for (int n = 1; std::getline(in, line); ++n)
	{
		const std::string t = trimmed(line);
		const std::string where = path + ": line " + std::to_string(n);
		if (t.empty() || t[0] == '#' || t[0] == ';' || t.rfind("//", 0) == 0 || t[0] == '@') continue;
		if (t[0] == '[')
		{
			const auto close = t.find(']');
			const std::string rest = close == std::string::npos ? "" : trimmed(t.substr(close + 1));
			if (close == std::string::npos || close < 2 || !(rest.empty() || rest[0] == '#' || rest[0] == ';'))
				failInput(where, "malformed section header '" + printable(t) + "'");
			section = true;
			continue;
		}
		const auto eq = t.find('=');
		if (eq == std::string::npos || trimmed(t.substr(0, eq)).empty())
			failInput(where, "'" + printable(t) + "' is not 'key = value', a [section] or a comment: is this an INI file?");
		if (!section) failInput(where, "'" + printable(t) + "' comes before any [section]");
	}
	if (!section) failInput(path, "no [section] in the file: is this an INI file? (see ini/ for examples)");
}
}  // namespace

RunConfig RunConfig::fromFile(const std::string& path, const std::vector<std::string>& overrides)
{
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

void RunConfig::setDefault(const std::string& section, const std::string& key, const std::string& value)
{
	if (!user_.keyExists(section, key)) user_.write(section, key, value);
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
}  // namespace vlo
