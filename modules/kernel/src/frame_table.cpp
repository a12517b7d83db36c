#include <vlo/core/atomic_file.h>
#include <vlo/kernel/frame_table.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace vlo::kernel
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

/// printf rounds -0.0001 to "-0.000": a sign on a zero says nothing and breaks textual comparisons.
std::string withoutNegativeZero(std::string s)
{
	if (!s.empty() && s[0] == '-' && s.find_first_not_of("0.", 1) == std::string::npos) s.erase(0, 1);
	return s;
}

std::string moduleOf(const std::string& column)
{
	return column.substr(0, column.find('_'));
}
}  // namespace

std::string FrameTable::Cell::text() const
{
	if (const auto* text = std::get_if<std::string>(&value)) return *text;
	if (const auto* count = std::get_if<long long>(&value)) return std::to_string(*count);
	const double v = std::get<double>(value);
	if (!std::isfinite(v)) return "nan";
	char buf[64];
	std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
	return withoutNegativeZero(buf);
}

double FrameTable::Cell::number() const
{
	if (const auto* count = std::get_if<long long>(&value)) return static_cast<double>(*count);
	const auto* v = std::get_if<double>(&value);
	return v && std::isfinite(*v) ? *v : NAN;
}

void FrameTable::newRow() { rows_.emplace_back(); }

void FrameTable::setCell(std::size_t row, const std::string& column, Cell cell)
{
	if (rows_.empty()) newRow();
	if (std::find(columns_.begin(), columns_.end(), column) == columns_.end()) columns_.push_back(column);
	rows_.at(row)[column] = std::move(cell);
}

void FrameTable::set(const std::string& column, const std::string& value) { setCell(column, {value}); }

void FrameTable::set(const std::string& column, double value, int decimals) { setCell(column, {value, decimals}); }

void FrameTable::set(const std::string& column, long long value) { setCell(column, {value}); }

void FrameTable::setTimes(const std::string& prefix, const StageTimes& times)
{
	for (const auto& [stage, ms] : times.stages()) set("ms_" + prefix + stage, ms, 2);
}

void FrameTable::setCells(const FrameTable& part)
{
	if (part.rows_.empty()) return;
	const auto& row = part.rows_.back();
	for (const auto& c : part.columns_)
		if (const auto cell = row.find(c); cell != row.end()) setCell(c, cell->second);
}

void FrameTable::setCellsAt(std::size_t row, const FrameTable& part)
{
	if (part.rows_.empty()) return;
	if (row >= rows_.size()) throw std::out_of_range("frame table: no row " + std::to_string(row));
	const auto& cells = part.rows_.back();
	for (const auto& c : part.columns_)
		if (const auto cell = cells.find(c); cell != cells.end()) setCell(row, c, cell->second);
}

std::vector<std::string> FrameTable::columns() const
{
	static const std::vector<std::string> leading{"frame", "t", "x", "y", "z"};
	std::vector<std::string> modules;  // in the order each first wrote a column
	for (const auto& c : columns_)
		if (c.rfind("ms_", 0) != 0 && std::find(leading.begin(), leading.end(), c) == leading.end() &&
			std::find(modules.begin(), modules.end(), moduleOf(c)) == modules.end())
			modules.push_back(moduleOf(c));
	const auto rank = [&](const std::string& c) -> std::size_t {
		const auto lead = std::find(leading.begin(), leading.end(), c);
		if (lead != leading.end()) return static_cast<std::size_t>(lead - leading.begin());
		const bool timing = c.rfind("ms_", 0) == 0;
		if (c == "ms_total") return std::numeric_limits<std::size_t>::max();
		const std::string m = moduleOf(timing ? c.substr(3) : c);
		const auto mi = static_cast<std::size_t>(std::find(modules.begin(), modules.end(), m) - modules.begin());
		return leading.size() + (timing ? modules.size() + 1 : 0) + mi;
	};
	std::vector<std::string> ordered = columns_;
	std::stable_sort(ordered.begin(), ordered.end(), [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
	return ordered;
}

std::string FrameTable::cell(std::size_t row, const std::string& column) const
{
	const auto& r = rows_.at(row);
	const auto it = r.find(column);
	return it == r.end() ? "" : it->second.text();
}

std::vector<double> FrameTable::numbers(const std::string& column) const
{
	std::vector<double> v;
	v.reserve(rows_.size());
	for (const auto& r : rows_)
	{
		const auto it = r.find(column);
		v.push_back(it == r.end() ? NAN : it->second.number());
	}
	return v;
}

void FrameTable::write(const std::string& path) const
{
	const std::vector<std::string> order = columns();
	AtomicOutputFile f(path);
	auto& out = f.stream();
	for (std::size_t c = 0; c < order.size(); ++c) out << (c ? "," : "") << order[c];
	out << '\n';
	for (const auto& r : rows_)
	{
		for (std::size_t c = 0; c < order.size(); ++c)
		{
			const auto it = r.find(order[c]);
			out << (c ? "," : "") << (it == r.end() ? "" : csvCell(it->second.text()));
		}
		out << '\n';
	}
	f.commit();
}
}  // namespace vlo::kernel
