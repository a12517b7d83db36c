#pragma once
// A cap on the size of one allocation on this thread, for reading untrusted files.
#include <cstddef>

namespace vlo
{
/// While alive, an mrpt::aligned_malloc or operator new above `max_bytes` on this thread throws
/// std::bad_alloc (see allocation_limit.cpp for why MRPT cannot be trusted with a corrupt count).
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
}  // namespace vlo
