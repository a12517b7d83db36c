#include <vlo/core/error.h>
#include <vlo/kernel/run_config.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vlo
{
namespace
{
std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r\n");
	if (b == std::string::npos) return "";
	return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

bool parsesAs(const std::string& v, bool integer)
{
	if (v.empty()) return false;
	char* end = nullptr;
	if (integer)
		(void)std::strtol(v.c_str(), &end, 10);
	else
		(void)std::strtod(v.c_str(), &end);
	return *end == '\0';
}

bool isBoolText(const std::string& v)
{
	for (const char* b : {"true", "false", "1", "0", "yes", "no", "TRUE", "FALSE", "True", "False"})
		if (v == b) return true;
	return false;
}

/// MRPT silently reads "abc" as 0: reject a user value whose form differs from the default's.
void checkValueType(const std::string& origin, const std::string& section, const std::string& key,
	const std::string& defaultText, const std::string& userText)
{
	const std::string d = trim(defaultText), u = trim(userText);
	const std::string where = origin + ": [" + section + "] " + key;
	if (d == "true" || d == "false")
	{
		if (!isBoolText(u)) failInput(where, "expects true or false, got '" + u + "'");
	}
	else if (parsesAs(d, true))
	{
		if (!parsesAs(u, true)) failInput(where, "expects an integer, got '" + u + "'");
	}
	else if (parsesAs(d, false))
	{
		if (!parsesAs(u, false)) failInput(where, "expects a number, got '" + u + "'");
	}
}
/// A file the user gives as an INI must look like one: text, every line a comment, a [section], a
/// key = value inside a section, or an MRPT @directive; and at least one section.
/// Up to 60 characters of a line for a message, unprintable ones shown as '?'.
std::string quoted(const std::string& line)
{
	std::string q = line.substr(0, 60);
	for (char& c : q)
		if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
	return "'" + q + "'";
}

void checkIniSyntax(const std::string& text, const std::string& path)
{
	if (text.find('\0') != std::string::npos) failInput(path, "not an INI file (binary content)");
	std::istringstream in(text);
	std::string line;
	bool section = false;
	for (int n = 1; std::getline(in, line); ++n)
	{
		const std::string t = trim(line);
		const std::string where = path + ": line " + std::to_string(n);
		if (t.empty() || t[0] == '#' || t[0] == ';' || t.rfind("//", 0) == 0 || t[0] == '@') continue;
		if (t[0] == '[')
		{
			const auto close = t.find(']');
			const std::string rest = close == std::string::npos ? "" : trim(t.substr(close + 1));
			if (close == std::string::npos || close < 2 || !(rest.empty() || rest[0] == '#' || rest[0] == ';'))
				failInput(where, "malformed section header " + quoted(t));
			section = true;
			continue;
		}
		const auto eq = t.find('=');
		if (eq == std::string::npos || trim(t.substr(0, eq)).empty())
			failInput(where, quoted(t) + " is not 'key = value', a [section] or a comment: is this an INI file?");
		if (!section) failInput(where, quoted(t) + " comes before any [section]");
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
		cfg.user_.write(o.substr(0, lastDot), o.substr(lastDot + 1, eq - lastDot - 1), o.substr(eq + 1));
	}
	return cfg;
}

void RunConfig::setDefault(const std::string& section, const std::string& key, const std::string& value)
{
	if (!user_.keyExists(section, key)) user_.write(section, key, value);
}

void RunConfig::load(mrpt::config::CLoadableOptions& opts, const std::string& section)
{
	opts.loadFromConfigFile(user_, section);
	mrpt::config::CConfigFileMemory saved;
	opts.saveToConfigFile(saved, section);
	std::vector<std::string> keys;
	saved.getAllKeys(section, keys);
	known_sections_.insert(section);
	for (const auto& padded : keys)
	{
		// MRPT_SAVE_CONFIG_VAR_COMMENT pads names for alignment: compare trimmed names.
		const std::string k = trim(padded);
		known_.insert({section, k});
		const std::string value = trim(saved.read_string(section, padded, ""));
		if (user_.keyExists(section, k))
			checkValueType(origin_, section, k, value, user_.read_string(section, k, ""));
	}
	opts.saveToConfigFile(effective_, section);  // with MRPT's comments on each key
}

void RunConfig::checkAllKeysUsed() const
{
	std::vector<std::string> sections;
	user_.getAllSections(sections);
	for (const auto& s : sections)
	{
		if (s.empty()) continue;  // @define lines live outside any section
		if (!known_sections_.count(s)) failInput(origin_, "unknown section [" + s + "]");
		std::vector<std::string> keys;
		user_.getAllKeys(s, keys);
		for (const auto& k : keys)
			if (!known_.count({s, trim(k)})) failInput(origin_, "unknown key '" + k + "' in section [" + s + "]");
	}
}
}  // namespace vlo
