#pragma once
// What MRPT's INI reader does not tell: the order of sections, lines that are no INI at all, and keys or
// sections given twice (it keeps the last value silently). Every INI a user gives (vlo-run's --ini,
// vlo-batch's plans) is scanned with this before MRPT reads the values.
#include <string>
#include <vector>

namespace vlo
{
struct IniSection
{
	std::string name;  ///< as MRPT sees it: the text between [ and ], trimmed
	int line = 0;
	std::vector<std::string> keys;  ///< in file order
};

/// Sections in file order. Throws InputError(origin, ...) for binary content; with the line number for a
/// line that is neither a comment (#, ;, //), a [section], "key = value" nor an MRPT @directive; for a key
/// outside a section; and for a section or a key of a section given twice.
std::vector<IniSection> scanIniText(const std::string& text, const std::string& origin);
}  // namespace vlo
