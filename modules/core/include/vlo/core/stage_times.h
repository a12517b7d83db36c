#pragma once
// Milliseconds per stage of one frame: what every estimator reports and every adapter copies into
// frames.csv (one ms_<prefix><stage> column per stage, in the declared order).
//
//   StageTimes ms{{"features", "odometry", "mapping"}};
//   auto t0 = SteadyClock::now();
//   ...; ms.add("features", lapMs(t0));  // a stage that runs in pieces adds up
#include <vlo/core/stopwatch.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace vlo
{
class StageTimes
{
   public:
	/// The stages in report order, each at 0 ms (a stage skipped this frame still reports 0).
	explicit StageTimes(const std::vector<std::string>& stages);

	/// Adds ms to `stage`; throws std::logic_error for a stage that was not declared (a typo in code).
	void add(const std::string& stage, double ms);
	/// Milliseconds of `stage` (throws std::logic_error like add).
	double ms(const std::string& stage) const;
	/// The sum over all stages.
	double total() const;
	const std::vector<std::pair<std::string, double>>& stages() const { return stages_; }

   private:
	std::size_t index(const std::string& stage) const;
	std::vector<std::pair<std::string, double>> stages_;
};
}  // namespace vlo
