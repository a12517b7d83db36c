// The limit only: what enforces it replaces process-wide symbols, and is an opt-in library of its own
// (corrupt_input_guard/allocation_guard.cpp says why).
#include <vlo/io/allocation_limit.h>

#include <limits>

namespace vlo::io
{
namespace
{
thread_local std::size_t max_allocation = std::numeric_limits<std::size_t>::max();
}

ScopedAllocationLimit::ScopedAllocationLimit(std::size_t max_bytes) : previous_(max_allocation)
{
	max_allocation = max_bytes;
}

ScopedAllocationLimit::~ScopedAllocationLimit() { max_allocation = previous_; }

std::size_t allocationLimit() noexcept { return max_allocation; }
}  // namespace vlo::io
