#pragma once
// Milliseconds of wall time, for the per-stage timings every module reports.
#include <chrono>

namespace vlo
{
using SteadyClock = std::chrono::steady_clock;

/// Milliseconds since t0.
inline double msSince(SteadyClock::time_point t0)
{
	return std::chrono::duration<double, std::milli>(SteadyClock::now() - t0).count();
}

/// Milliseconds since t0, then moves t0 to now: times consecutive stages with one variable.
inline double lapMs(SteadyClock::time_point& t0)
{
	const auto t1 = SteadyClock::now();
	const double ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
	t0 = t1;
	return ms;
}
}  // namespace vlo
