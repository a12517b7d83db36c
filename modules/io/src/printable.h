#pragma once
// Text from a file quoted in an error message: errors are one printable line, whatever the file holds.
#include <string>

namespace vlo::io
{
/// `text` with control bytes (a carriage return, a NUL, an escape from a corrupt file) as '?'.
inline std::string printable(std::string text)
{
	for (char& c : text)
		if ((static_cast<unsigned char>(c) < 32 && c != '\t') || c == 127) c = '?';
	return text;
}
}  // namespace vlo::io
