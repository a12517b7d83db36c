#include <vlo/core/error.h>
#include <vlo/core/ini_text.h>
#include <vlo/core/option_table.h>

#include <sstream>

namespace vlo
{
std::vector<IniSection> scanIniText(const std::string& text, const std::string& origin)
{
	if (text.find('\0') != std::string::npos) failInput(origin, "not an INI file (binary content)");
	std::vector<IniSection> sections;
	std::istringstream in(text);
	std::string raw;
	for (int n = 1; std::getline(in, raw); ++n)
	{
		const std::string t = trimmed(raw);
		const std::string at = origin + ": line " + std::to_string(n);
		if (t.empty() || t[0] == '#' || t[0] == ';' || t.rfind("//", 0) == 0 || t[0] == '@') continue;
		if (t[0] == '[')
		{
			const auto close = t.find(']');
			const std::string rest = close == std::string::npos ? "" : trimmed(t.substr(close + 1));
			if (close == std::string::npos || close < 2 || !(rest.empty() || rest[0] == '#' || rest[0] == ';'))
				failInput(at, "malformed section header '" + printable(t) + "'");
			const std::string name = trimmed(t.substr(1, close - 1));
			for (const auto& s : sections)
				if (s.name == name)
					failInput(at,
						"section [" + printable(name) + "] given twice (also line " +
							std::to_string(s.line) + "; MRPT would merge them silently)");
			sections.push_back({name, n, {}});
			continue;
		}
		const auto eq = t.find('=');
		const std::string key = eq == std::string::npos ? "" : trimmed(t.substr(0, eq));
		if (key.empty())
			failInput(at, "'" + printable(t) + "' is not 'key = value', a [section] or a comment: is this an INI file?");
		if (sections.empty()) failInput(at, "'" + printable(t) + "' comes before any [section]");
		auto& keys = sections.back().keys;
		for (const auto& k : keys)
			if (k == key)
				failInput(at,
					"[" + printable(sections.back().name) + "] " + printable(key) +
						": given twice (MRPT would keep only the last; put every value on one line)");
		keys.push_back(key);
	}
	return sections;
}
}  // namespace vlo
