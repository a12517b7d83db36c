#pragma once
// The per-frame table written as frames.csv: each module sets its own columns for the current row;
// the column order is the order in which columns first appeared. Missing cells stay empty.
#include <map>
#include <string>
#include <vector>

namespace vlo
{
class FrameTable
{
   public:
	/// Starts a new row; later set() calls fill it.
	void newRow();
	void set(const std::string& column, const std::string& value);
	void set(const std::string& column, double value, int decimals = 4);
	void set(const std::string& column, long long value);
	void set(const std::string& column, bool value) { set(column, std::string(value ? "1" : "0")); }

	std::size_t rows() const { return rows_.size(); }
	const std::vector<std::string>& columns() const { return columns_; }
	/// Cell text ("" when never set); throws std::out_of_range for a bad row.
	std::string cell(std::size_t row, const std::string& column) const;
	/// Numeric column values, NaN where empty or not a number.
	std::vector<double> numbers(const std::string& column) const;

	/// Writes CSV atomically.
	void write(const std::string& path) const;

   private:
	std::vector<std::string> columns_;
	std::vector<std::map<std::string, std::string>> rows_;
};
}  // namespace vlo
