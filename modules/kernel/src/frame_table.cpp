#include <vlo/core/atomic_file.h>
#include <vlo/kernel/frame_table.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace vlo
{
namespace
{
/// RFC 4180: quote cells holding a comma, quote or line break.
std::string csvCell(const std::string& s)
{
	if (s.find_first_of(",\"\n") == std::string::npos) return s;
	std::string q = "\"";
	for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
	return q + "\"";
}
}  // namespace

void FrameTable::newRow() { rows_.emplace_back(); }

void FrameTable::set(const std::string& column, const std::string& value)
{
	if (rows_.empty()) newRow();
	if (std::find(columns_.begin(), columns_.end(), column) == columns_.end()) columns_.push_back(column);
	rows_.back()[column] = value;
}

void FrameTable::set(const std::string& column, double value, int decimals)
{
	if (!std::isfinite(value)) return set(column, std::string("nan"));
	char buf[64];
	std::snprintf(buf, sizeof(buf), "%.*f", decimals, value);
	set(column, std::string(buf));
}

void FrameTable::set(const std::string& column, long long value) { set(column, std::to_string(value)); }

std::string FrameTable::cell(std::size_t row, const std::string& column) const
{
	const auto& r = rows_.at(row);
	const auto it = r.find(column);
	return it == r.end() ? "" : it->second;
}

std::vector<double> FrameTable::numbers(const std::string& column) const
{
	std::vector<double> v;
	v.reserve(rows_.size());
	for (std::size_t i = 0; i < rows_.size(); ++i)
	{
		const std::string s = cell(i, column);
		char* end = nullptr;
		const double d = std::strtod(s.c_str(), &end);
		v.push_back(s.empty() || *end != '\0' ? NAN : d);
	}
	return v;
}

void FrameTable::write(const std::string& path) const
{
	AtomicOutputFile f(path);
	auto& out = f.stream();
	for (std::size_t c = 0; c < columns_.size(); ++c) out << (c ? "," : "") << columns_[c];
	out << '\n';
	for (const auto& r : rows_)
	{
		for (std::size_t c = 0; c < columns_.size(); ++c)
		{
			const auto it = r.find(columns_[c]);
			out << (c ? "," : "") << (it == r.end() ? "" : csvCell(it->second));
		}
		out << '\n';
	}
	f.commit();
}
}  // namespace vlo
