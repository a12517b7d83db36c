#pragma once
// What MRPT's INI reader does not tell: the order of sections, and keys or sections given twice
// (it keeps the last value silently). Plans are scanned with this before MRPT reads the values.
#include <string>
#include <vector>

namespace vlo::batch
{
struct IniSection
{
	std::string name;  ///< as MRPT sees it: the text between [ and ], trimmed
	int line = 0;
	std::vector<std::string> keys;  ///< in file order
};

/// Sections in file order. Throws InputError(origin, ...) with the line number for a line that is
/// neither a comment, a section, "key = value" nor an MRPT @define; for a key outside a section; and
/// for a repeated section or key.
std::vector<IniSection> scanIniText(const std::string& text, const std::string& origin);
}  // namespace vlo::batch
