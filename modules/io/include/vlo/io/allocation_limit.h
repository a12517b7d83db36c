#pragma once
// A cap on the size of one allocation on this thread, for reading untrusted files.
#include <cstddef>

namespace vlo::io
{
/// While alive, asks that an mrpt::aligned_malloc or operator new above `max_bytes` on this thread throw
/// std::bad_alloc. Only a program that links vlo::corrupt_input_guard (modules/io/corrupt_input_guard/,
/// the apps do) enforces it; elsewhere it changes nothing.
class ScopedAllocationLimit
{
   public:
	explicit ScopedAllocationLimit(std::size_t max_bytes);
	~ScopedAllocationLimit();
	ScopedAllocationLimit(const ScopedAllocationLimit&) = delete;
	ScopedAllocationLimit& operator=(const ScopedAllocationLimit&) = delete;

   private:
	std::size_t previous_;
};

/// The largest allocation this thread may make now (SIZE_MAX outside a ScopedAllocationLimit).
std::size_t allocationLimit() noexcept;
}  // namespace vlo::io
