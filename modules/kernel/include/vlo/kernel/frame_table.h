#pragma once
// The per-frame table written as frames.csv: each module sets its own columns for the current row.
// Missing cells stay empty. Cells keep what they were given (text, a count, a number and its decimals):
// the numbers are read back as they are, and turned into text once, when the CSV is written.
// Column order (doc/FORMATS.md): frame, t, x, y, z; then each module's columns; then the milliseconds
// (ms_*), ms_total last.
#include <vlo/core/stage_times.h>

#include <map>
#include <string>
#include <variant>
#include <vector>

namespace vlo::kernel
{
class FrameTable
{
   public:
	/// Starts a new row; later set() calls fill it.
	void newRow();
	void set(const std::string& column, const std::string& value);
	/// Fixed decimals; a value that rounds to zero is written without a sign ("0.000", never "-0.000").
	void set(const std::string& column, double value, int decimals = 4);
	void set(const std::string& column, long long value);
	void set(const std::string& column, bool value) { set(column, static_cast<long long>(value)); }
	/// One column ms_<prefix><stage> per stage, in the stages' order, 2 decimals.
	void setTimes(const std::string& prefix, const StageTimes& times);
	/// Sets the cells of `part`'s last row in the current row, in the order `part` first saw its
	/// columns: a stage that ran on another thread wrote into a table of its own (one per frame), and
	/// merging it in the stages' order gives the table the serial run would have made.
	void setCells(const FrameTable& part);
	/// The same into an earlier row: a stage whose result for a frame comes later (loop closure, whose
	/// thread handles a keyframe some frames after its row was written). Throws std::out_of_range.
	void setCellsAt(std::size_t row, const FrameTable& part);

	std::size_t rows() const { return rows_.size(); }
	/// In the CSV's order: the leading columns, then modules by the order each first wrote (a module
	/// is the prefix up to the first '_': vo, scale, lo), each module's columns in first-seen order;
	/// then the ms_<module>* columns in the same module order, ms_total last.
	std::vector<std::string> columns() const;
	/// Cell text as frames.csv has it ("" when never set); throws std::out_of_range for a bad row.
	std::string cell(std::size_t row, const std::string& column) const;
	/// Numeric column values as they were set (not as rounded for the CSV), NaN where empty, text or not finite.
	std::vector<double> numbers(const std::string& column) const;

	/// Writes CSV atomically.
	void write(const std::string& path) const;

   private:
	/// Text, a count (flags are 0 or 1), or a number written with `decimals` fixed decimals.
	struct Cell
	{
		std::variant<std::string, long long, double> value;
		int decimals = 0;
		std::string text() const;
		double number() const;
	};
	void setCell(const std::string& column, Cell cell) { setCell(rows_.empty() ? 0 : rows_.size() - 1, column, std::move(cell)); }
	void setCell(std::size_t row, const std::string& column, Cell cell);

	std::vector<std::string> columns_;
	std::vector<std::map<std::string, Cell>> rows_;
};
}  // namespace vlo::kernel
