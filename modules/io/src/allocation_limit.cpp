// MRPT 2.5.8 deserialises a count, then resizes to it, then reads the data. With a corrupt count:
// - mrpt::aligned_malloc (behind every mrpt::aligned_std_vector, e.g. CPointsMapXYZI::serializeFrom)
//   returns null when memory runs out and the vector writes through it: a segfault under a memory
//   limit, tens of GB allocated and zeroed without one;
// - a std::string or std::vector (e.g. in CObservationVelodyneScan) is resized to up to 4 GB and zeroed
//   before the short read is noticed: seconds and gigabytes per corrupt object.
// These definitions take the place of MRPT's aligned_malloc and of the global operator new for the
// whole program (the executable's symbols win over the shared libraries'; MRPT's size rounding kept),
// throw std::bad_alloc instead of returning null, and honour ScopedAllocationLimit, which is only set
// while a rawlog object is being deserialised. Under AddressSanitizer, whose allocator must see every
// new and delete, operator new is left alone.
#include "allocation_limit.h"

#include <cstdlib>
#include <limits>
#include <new>

namespace
{
thread_local std::size_t max_allocation = std::numeric_limits<std::size_t>::max();
}

namespace vlo
{
ScopedAllocationLimit::ScopedAllocationLimit(std::size_t max_bytes) : previous_(max_allocation)
{
	max_allocation = max_bytes;
}

ScopedAllocationLimit::~ScopedAllocationLimit() { max_allocation = previous_; }
}  // namespace vlo

namespace mrpt
{
void* aligned_malloc(std::size_t size, std::size_t alignment);

void* aligned_malloc(std::size_t size, std::size_t alignment)
{
	if (size > max_allocation) throw std::bad_alloc();
	if (alignment != 0 && size % alignment != 0) size = (size / alignment + 1) * alignment;
	void* p = std::aligned_alloc(alignment, size);
	if (!p && size != 0) throw std::bad_alloc();
	return p;
}
}  // namespace mrpt

#if defined(__has_feature)
#if __has_feature(address_sanitizer)  // clang's spelling of GCC's __SANITIZE_ADDRESS__
#define __SANITIZE_ADDRESS__ 1
#endif
#endif
#if !defined(__SANITIZE_ADDRESS__)
void* operator new(std::size_t size)
{
	if (size > max_allocation) throw std::bad_alloc();
	for (;;)  // the standard's behaviour: retry while a new_handler frees memory
	{
		if (void* p = std::malloc(size ? size : 1)) return p;
		const std::new_handler handler = std::get_new_handler();
		if (!handler) throw std::bad_alloc();
		handler();
	}
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#endif
