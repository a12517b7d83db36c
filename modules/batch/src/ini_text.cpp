#include "ini_text.h"

#include <vlo/core/error.h>

#include <sstream>

namespace vlo::batch
{
namespace
{
std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r");
	if (b == std::string::npos) return "";
	return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}
}  // namespace

std::vector<IniSection> scanIniText(const std::string& text, const std::string& origin)
{
	std::vector<IniSection> sections;
	std::istringstream in(text);
	std::string raw;
	for (int n = 1; std::getline(in, raw); ++n)
	{
		const std::string line = trim(raw);
		const std::string at = origin + ": line " + std::to_string(n);
		if (line.empty() || line[0] == '#' || line[0] == ';' || line.rfind("@define", 0) == 0) continue;
		if (line[0] == '[')
		{
			if (line.back() != ']') failInput(at, "a section header must end with ']'");
			const std::string name = trim(line.substr(1, line.size() - 2));
			for (const auto& s : sections)
				if (s.name == name)
					failInput(at, "section [" + name + "] given twice (also line " + std::to_string(s.line) + ")");
			sections.push_back({name, n, {}});
			continue;
		}
		const auto eq = line.find('=');
		if (eq == std::string::npos) failInput(at, "expected 'key = value', a [section] or a comment, got '" + line + "'");
		const std::string key = trim(line.substr(0, eq));
		if (key.empty()) failInput(at, "no key before '='");
		if (sections.empty()) failInput(at, "key '" + key + "' before the first [section]");
		auto& keys = sections.back().keys;
		for (const auto& k : keys)
			if (k == key)
				failInput(at, "[" + sections.back().name + "] " + key +
						": given twice (MRPT would keep only the last; put every value on one line)");
		keys.push_back(key);
	}
	return sections;
}
}  // namespace vlo::batch
