#include <vlo/batch/words.h>
#include <vlo/core/error.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace vlo::batch
{
std::vector<std::string> splitWords(const std::string& text, const std::string& where)
{
	std::vector<std::string> words;
	std::string w;
	bool inWord = false, quoted = false;
	for (const char c : text)
	{
		if (c == '"')
		{
			quoted = !quoted;
			inWord = true;  // "" is an empty word
		}
		else if (!quoted && (c == ' ' || c == '\t'))
		{
			if (inWord) words.push_back(w);
			w.clear();
			inWord = false;
		}
		else
		{
			w += c;
			inWord = true;
		}
	}
	if (quoted) failInput(where, "unterminated \" in '" + text + "'");
	if (inWord) words.push_back(w);
	return words;
}

std::string shellQuote(const std::string& word)
{
	bool safe = !word.empty();
	for (const char c : word)
		if (!(std::isalnum(static_cast<unsigned char>(c)) || std::string("@%+=:,./_-").find(c) != std::string::npos))
			safe = false;
	if (safe) return word;
	std::string q = "'";
	for (const char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
	return q + "'";
}

std::string shellJoin(const std::vector<std::string>& words)
{
	std::string s;
	for (const auto& w : words) s += (s.empty() ? "" : " ") + shellQuote(w);
	return s;
}

std::string joinWords(const std::vector<std::string>& words)
{
	std::string s;
	for (const auto& w : words)
	{
		const bool quote = w.empty() || w.find_first_of(" \t") != std::string::npos;
		s += (s.empty() ? "" : " ") + (quote ? "\"" + w + "\"" : w);
	}
	return s;
}

std::string numberWord(double v)
{
	char buf[32];
	for (int digits = 6; digits <= 17; ++digits)
	{
		std::snprintf(buf, sizeof buf, "%.*g", digits, v);
		if (std::strtod(buf, nullptr) == v) break;
	}
	return buf;
}
}  // namespace vlo::batch
