#pragma once
// One self-overwriting progress line (count, rate, ETA) on stderr when it is a terminal; silent
// otherwise so that logs and CI output stay clean.
#include <chrono>
#include <cstddef>
#include <string>

namespace vlo
{
class ProgressLine
{
   public:
	/// total = 0 when unknown (no ETA is shown).
	ProgressLine(std::string label, std::size_t total);
	~ProgressLine();
	/// `fraction` in [0, 1] of the whole job when the total count is unknown (e.g. bytes read).
	/// Throws Interrupted after Ctrl-C (interrupt.h).
	void update(std::size_t done, double fraction = -1);
	void finish();
	static void setEnabled(bool on);  ///< force on/off (tests, --quiet)

   private:
	std::string label_;
	std::size_t total_, done_ = 0;
	std::chrono::steady_clock::time_point start_, last_;
	bool printed_ = false;
};
}  // namespace vlo
