#include <mrpt/config/CConfigFileMemory.h>
#include <vlo/core/option_table.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace vlo
{
namespace
{
double parseNumber(const std::string& t)
{
	char* end = nullptr;
	const double v = std::strtod(t.c_str(), &end);
	if (t.empty() || *end != '\0') throw "expects a number, got '" + printable(t) + "'";
	if (!std::isfinite(v)) throw "expects a finite number, got '" + printable(t) + "'";
	return v;
}

int parseInt(const std::string& t)
{
	char* end = nullptr;
	errno = 0;
	const long v = std::strtol(t.c_str(), &end, 10);
	if (t.empty() || *end != '\0') throw "expects an integer, got '" + printable(t) + "'";
	if (errno == ERANGE || v < INT_MIN || v > INT_MAX) throw "the integer '" + printable(t) + "' is out of range";
	return static_cast<int>(v);
}

std::string joined(const std::vector<std::string>& words, const char* sep)
{
	std::string out;
	for (const auto& w : words) out += (out.empty() ? "" : sep) + w;
	return out;
}

std::size_t editDistance(const std::string& a, const std::string& b)
{
	std::vector<std::size_t> row(b.size() + 1);
	for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
	for (std::size_t i = 1; i <= a.size(); ++i)
	{
		std::size_t diagonal = row[0];
		row[0] = i;
		for (std::size_t j = 1; j <= b.size(); ++j)
		{
			const std::size_t up = row[j];
			row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
			diagonal = up;
		}
	}
	return row[b.size()];
}
}  // namespace

Range Range::parse(const std::string& text)
{
	Range r;
	r.written = text;
	if (text == "any") return r;
	const auto bad = [&text] { return std::logic_error("option range '" + text + "' is not '> a', '>= a', '(a, b]' ..."); };
	char* end = nullptr;
	if (text[0] == '>')
	{
		const bool closed = text.size() > 1 && text[1] == '=';
		r.lo = std::strtod(text.c_str() + (closed ? 2 : 1), &end);
		r.lo_open = !closed;
		if (*end != '\0') throw bad();
		return r;
	}
	const auto comma = text.find(',');
	if (text.size() < 5 || comma == std::string::npos || (text[0] != '(' && text[0] != '[') ||
		(text.back() != ')' && text.back() != ']'))
		throw bad();
	r.lo = std::strtod(text.c_str() + 1, &end);
	if (end != text.c_str() + comma) throw bad();
	r.hi = std::strtod(text.c_str() + comma + 1, &end);
	if (end != text.c_str() + text.size() - 1) throw bad();
	r.lo_open = text[0] == '(';
	r.hi_open = text.back() == ')';
	return r;
}

bool Range::contains(double v) const
{
	return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::text() const
{
	if (written == "any") return "";
	return "must be " + std::string(written[0] == '>' ? "" : "in ") + written;
}

namespace
{
/// Writes `field` as MRPT_SAVE_CONFIG_VAR_COMMENT would.
template <class T>
auto saver(const T& field)
{
	return [&field](mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& k, const std::string& h) {
		c.write(s, k, field, mrpt::config::MRPT_SAVE_NAME_PADDING(), mrpt::config::MRPT_SAVE_VALUE_PADDING(), h);
	};
}

/// "" when `v` is within `range`, else what it must be.
template <class T>
auto checker(const T& field, const Range& range)
{
	return [&field, range] { return range.contains(field) ? "" : range.text(); };
}

std::vector<std::string> words(const std::string& alternatives)
{
	std::vector<std::string> out;
	std::istringstream in(alternatives);
	for (std::string w; in >> w;)
		if (w != "|") out.push_back(w);
	return out;
}
}  // namespace

void OptionTable::add(const char* key, double& field, const char* allowed, const char* help)
{
	const Range range = Range::parse(allowed);
	add({key, help, allowed, [&field](const std::string& t) { field = parseNumber(t); }, checker(field, range), saver(field)});
}

void OptionTable::add(const char* key, int& field, const char* allowed, const char* help)
{
	const Range range = Range::parse(allowed);
	add({key, help, allowed, [&field](const std::string& t) { field = parseInt(t); }, checker(field, range), saver(field)});
}

void OptionTable::add(const char* key, bool& field, const char* allowed, const char* help)
{
	if (std::string(allowed) != "true | false") throw std::logic_error(std::string("flag ") + key + ": allowed must be 'true | false'");
	const auto parse = [&field](const std::string& t) {
		if (!parseBool(t, field)) throw "expects true or false, got '" + printable(t) + "'";
	};
	add({key, help, allowed, parse, [] { return std::string(); }, saver(field)});
}

void OptionTable::add(const char* key, std::string& field, const char* allowed, const char* help)
{
	const std::vector<std::string> choices = std::string(allowed) == "any" ? std::vector<std::string>{} : words(allowed);
	const auto check = [&field, choices] {
		if (choices.empty() || std::find(choices.begin(), choices.end(), field) != choices.end()) return std::string();
		return notOneOf(field, choices);
	};
	add({key, help, allowed, [&field](const std::string& t) { field = t; }, check, saver(field)});
}

void OptionTable::add(const char* key, std::vector<double>& field, const char* allowed, const char* help)
{
	const Range range = Range::parse(allowed);
	const auto parse = [&field](const std::string& t) {
		std::string inner = t;
		if (!inner.empty() && inner.front() == '[' && inner.back() == ']') inner = inner.substr(1, inner.size() - 2);
		std::vector<double> values;
		std::istringstream in(inner);
		for (std::string w; in >> w;)
		{
			if (!w.empty() && w.back() == ',') w.pop_back();
			try
			{
				values.push_back(parseNumber(w));
			}
			catch (const std::string&)
			{
				throw "expects a list of numbers like [1.5 -2 3], got '" + printable(t) + "'";
			}
		}
		field = values;
	};
	const auto check = [&field, range] {
		for (double v : field)
			if (!range.contains(v)) return "each value " + range.text();
		return std::string();
	};
	const auto save = [&field](mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& k, const std::string& h) {
		std::ostringstream list;
		list << "[";
		for (std::size_t i = 0; i < field.size(); ++i) list << (i ? " " : "") << field[i];
		list << "]";
		c.write(s, k, list.str(), mrpt::config::MRPT_SAVE_NAME_PADDING(), mrpt::config::MRPT_SAVE_VALUE_PADDING(), h);
	};
	add({key, help, std::string("list, each ") + allowed, parse, check, save});
}

void OptionTable::load(const mrpt::config::CConfigFileBase& c, const std::string& section)
{
	for (const auto& e : entries_)
	{
		if (!c.keyExists(section, e.key)) continue;
		try
		{
			e.parse(trimmed(c.read_string(section, e.key, "")));
		}
		catch (const std::string& problem)
		{
			throw OptionError(section, e.key, problem);
		}
		const std::string problem = e.check();
		if (!problem.empty()) throw OptionError(section, e.key, problem);
	}
}

void OptionTable::check() const
{
	for (const auto& e : entries_)
	{
		const std::string problem = e.check();
		if (!problem.empty()) throw OptionError("", e.key, problem);
	}
}

void OptionTable::save(mrpt::config::CConfigFileBase& c, const std::string& section) const
{
	for (const auto& e : entries_) e.save(c, section, e.key, e.help);
}

std::vector<OptionRow> OptionTable::rows() const
{
	mrpt::config::CConfigFileMemory saved;
	save(saved, "s");
	// Parsed again from the text: MRPT keeps the padding of the names it writes in memory.
	const mrpt::config::CConfigFileMemory text(saved.getContent());
	std::vector<OptionRow> out;
	for (const auto& e : entries_) out.push_back({e.key, trimmed(text.read_string("s", e.key, "")), e.allowed, e.help});
	return out;
}

void OptionSet::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& section)
{
	OptionTable t;
	declare(t);
	t.load(c, section);
	try
	{
		checkRelations();
	}
	catch (const OptionError& e)
	{
		throw OptionError(section, e.key(), e.problem());
	}
}

void OptionSet::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& section) const
{
	table().save(c, section);
}

void OptionSet::validate() const
{
	table().check();
	checkRelations();
}

std::vector<OptionRow> OptionSet::rows() const { return table().rows(); }

OptionTable OptionSet::table() const
{
	OptionTable t;
	// declare() only records where the fields are; through a const table they are only read.
	const_cast<OptionSet*>(this)->declare(t);
	return t;
}

void OptionSet::require(bool ok, const char* key, const std::string& problem)
{
	if (!ok) throw OptionError("", key, problem);
}

void OptionGroup::load(const mrpt::config::CConfigFileBase& c)
{
	for (const auto& [section, options] : parts()) options->loadFromConfigFile(c, section);
}

// parts() hands out pointers for loading; saving and validating only read through them.
void OptionGroup::save(mrpt::config::CConfigFileBase& c) const
{
	for (const auto& [section, options] : const_cast<OptionGroup*>(this)->parts()) options->saveToConfigFile(c, section);
}

void OptionGroup::validate() const
{
	for (const auto& [section, options] : const_cast<OptionGroup*>(this)->parts()) options->validate();
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& known)
{
	std::string best;
	std::size_t bestDistance = std::string::npos;
	for (const auto& k : known)
	{
		const std::size_t d = editDistance(word, k);
		if (d < bestDistance) best = k, bestDistance = d;
	}
	// A typo changes a few letters: at most a third of the word, at least 2, and never half of it or more
	// ("7" is no typo of "1").
	const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
	return bestDistance <= limit && 2 * bestDistance <= word.size() ? " (did you mean " + best + "?)" : "";
}

std::string notOneOf(const std::string& text, const std::vector<std::string>& allowed)
{
	return "'" + printable(text) + "' is not one of " + joined(allowed, ", ") + didYouMean(text, allowed);
}

std::string trimmed(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r\n");
	if (b == std::string::npos) return "";
	return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string printable(const std::string& text)
{
	std::string p = text.substr(0, 60);
	for (char& c : p)
		if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
	return p;
}

bool parseBool(const std::string& text, bool& value)
{
	for (const char* t : {"true", "True", "TRUE", "yes", "1"})
		if (text == t) return value = true, true;
	for (const char* f : {"false", "False", "FALSE", "no", "0"})
		if (text == f) return value = false, true;
	return false;
}
}  // namespace vlo
