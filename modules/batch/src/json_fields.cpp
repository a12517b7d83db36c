#include <vlo/batch/json_fields.h>
#include <vlo/core/error.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vlo::batch
{
namespace
{
struct Cursor
{
	const std::string& s;
	std::size_t i = 0;
	std::string origin;

	[[noreturn]] void fail(const std::string& what) const
	{
		failInput(origin, "not valid JSON (" + what + " at character " + std::to_string(i) + ")");
	}
	void blanks()
	{
		while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
	}
	char peek()
	{
		blanks();
		return i < s.size() ? s[i] : '\0';
	}
	void expect(char c)
	{
		if (peek() != c) fail(std::string("expected '") + c + "'");
		++i;
	}
	std::string string()
	{
		expect('"');
		std::string o;
		for (; i < s.size() && s[i] != '"'; ++i)
		{
			if (s[i] != '\\') o += s[i];
			else if (++i < s.size())
			{
				const char e = s[i];
				if (e == 'n') o += '\n';
				else if (e == 't') o += '\t';
				else if (e == 'u' && i + 4 < s.size())
				{
					o += static_cast<char>(std::strtol(s.substr(i + 1, 4).c_str(), nullptr, 16));  // ASCII only
					i += 4;
				}
				else o += e;
			}
		}
		expect('"');
		return o;
	}
	/// Skips a nested array or object, strings included.
	void skipNested()
	{
		int depth = 0;
		do
		{
			const char c = peek();
			if (c == '"') string();
			else if (c == '\0') fail("unterminated array or object");
			else
			{
				depth += (c == '[' || c == '{') ? 1 : (c == ']' || c == '}') ? -1 : 0;
				++i;
			}
		} while (depth > 0);
	}
	std::string scalar()
	{
		const std::size_t b = i;
		while (i < s.size() && s[i] != ',' && s[i] != '}' && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
		if (i == b) fail("expected a value");
		return s.substr(b, i - b);
	}
};
}  // namespace

JsonFields JsonFields::parse(const std::string& text, const std::string& origin)
{
	JsonFields f;
	Cursor c{text, 0, origin};
	c.expect('{');
	while (c.peek() != '}')
	{
		const std::string key = c.string();
		c.expect(':');
		const char v = c.peek();
		if (v == '"') f.values_[key] = c.string();
		else if (v == '[' || v == '{') c.skipNested();
		else f.values_[key] = c.scalar();
		if (c.peek() == ',') ++c.i;
		else if (c.peek() != '}') c.fail("expected ',' or '}'");
	}
	return f;
}

JsonFields JsonFields::read(const std::string& path)
{
	std::ifstream in(path);
	if (!in) failInput(path, "cannot open");
	std::stringstream ss;
	ss << in.rdbuf();
	return parse(ss.str(), path);
}

double JsonFields::number(const std::string& key) const
{
	const auto it = values_.find(key);
	if (it == values_.end()) return NAN;
	char* end = nullptr;
	const double d = std::strtod(it->second.c_str(), &end);
	return it->second.empty() || *end != '\0' ? NAN : d;
}

std::string JsonFields::text(const std::string& key) const
{
	const auto it = values_.find(key);
	return it == values_.end() ? "" : it->second;
}
}  // namespace vlo::batch
