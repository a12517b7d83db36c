// MRPT 2.5.8 deserialises a count, then resizes to it, then reads the data. With a corrupt count:
// - mrpt::aligned_malloc (behind every mrpt::aligned_std_vector, e.g. CPointsMapXYZI::serializeFrom)
//   returns null when memory runs out and the vector writes through it: a segfault under a memory
//   limit, tens of GB allocated and zeroed without one;
// - a std::string or std::vector (e.g. in CObservationVelodyneScan) is resized to up to 4 GB and zeroed
//   before the short read is noticed: seconds and gigabytes per corrupt object.
// MRPT offers no hook for either, so these definitions take the place of MRPT's aligned_malloc and of
// the global operator new in the program that links them (the executable's symbols win over the shared
// libraries'; MRPT's size rounding kept): they throw std::bad_alloc instead of returning null, and honour
// ScopedAllocationLimit, which the rawlog reader sets only while it deserialises an object.
// Under AddressSanitizer, whose allocator must see every new and delete, operator new is left alone
// (VLO_ADDRESS_SANITIZER is defined by cmake/sanitizers.cmake).
#include <vlo/io/allocation_limit.h>

#include <cstdlib>
#include <new>

namespace mrpt
{
void* aligned_malloc(std::size_t size, std::size_t alignment);

void* aligned_malloc(std::size_t size, std::size_t alignment)
{
	if (size > vlo::io::allocationLimit()) throw std::bad_alloc();
	if (alignment != 0 && size % alignment != 0) size = (size / alignment + 1) * alignment;
	void* p = std::aligned_alloc(alignment, size);
	if (!p && size != 0) throw std::bad_alloc();
	return p;
}
}  // namespace mrpt

#if !defined(VLO_ADDRESS_SANITIZER)
void* operator new(std::size_t size)
{
	if (size > vlo::io::allocationLimit()) throw std::bad_alloc();
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
