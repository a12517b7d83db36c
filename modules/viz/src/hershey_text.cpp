#include "hershey_text.h"

#include <cstdint>

namespace vlo::viz
{
namespace
{
/// ASCII for U+00C0..U+017F (Latin-1 letters and Latin Extended-A), "" where there is none.
std::string latinLetter(std::uint32_t c)
{
	static const char* const kC0[] = {"A", "A", "A", "A", "A", "A", "AE", "C", "E", "E", "E", "E", "I", "I", "I", "I",
		"D", "N", "O", "O", "O", "O", "O", "x", "O", "U", "U", "U", "U", "Y", "Th", "ss", "a", "a", "a", "a", "a", "a",
		"ae", "c", "e", "e", "e", "e", "i", "i", "i", "i", "d", "n", "o", "o", "o", "o", "o", "/", "o", "u", "u", "u",
		"u", "y", "th", "y"};
	if (c >= 0xC0 && c <= 0xFF) return kC0[c - 0xC0];
	// Latin Extended-A pairs an upper and a lower case letter: the base letters of U+0100..U+017F.
	static const char kExtA[] =
		"AaAaAaCcCcCcCcDdDdEeEeEeEeEeGgGgGgGgHhHhIiIiIiIiIiIiJjKkkLlLlLlLlLlNnNnNnnNnOoOoOoOoRrRrRrSsSsSsSsTtTtTtUuUuUuUuUuUu"
		"WwYyYZzZzZzs";
	static_assert(sizeof(kExtA) - 1 == 0x80, "one letter for each of U+0100..U+017F");
	if (c >= 0x100 && c <= 0x17F) return std::string(1, kExtA[c - 0x100]);
	return "";
}
}  // namespace

std::string hersheyText(const std::string& utf8)
{
	std::string out;
	for (std::size_t i = 0; i < utf8.size();)
	{
		const auto b = static_cast<unsigned char>(utf8[i]);
		if (b < 0x80)
		{
			out += static_cast<char>(b);
			++i;
			continue;
		}
		const int n = b >= 0xF0 ? 4 : b >= 0xE0 ? 3
			: b >= 0xC0                         ? 2
												: 1;  // a stray byte counts as one character
		std::uint32_t c = n == 1 ? b : b & (0x7F >> n);
		for (int k = 1; k < n && i + k < utf8.size(); ++k) c = (c << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
		i += n;
		const std::string latin = latinLetter(c);
		out += c == 0xB0 ? "deg" : c == 0xB5 ? "u"
			: !latin.empty()                 ? latin
											 : "?";
	}
	return out;
}
}  // namespace vlo::viz
