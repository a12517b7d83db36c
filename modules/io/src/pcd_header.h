#pragma once
// Internal: the header of a PCD v0.7 file and how to read one field of a packed binary point.
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace vlo
{
struct PcdField
{
	std::string name;
	int size = 4;  ///< bytes per element: 1, 2, 4 or 8
	char type = 'F';  ///< F float, I signed, U unsigned
	int count = 1;  ///< elements
	std::size_t offset = 0;  ///< bytes from the start of a binary point
	std::size_t value = 0;  ///< index of the first element among an ascii line's values
};

struct PcdHeader
{
	std::vector<PcdField> fields;
	std::size_t points = 0;
	bool binary = false;
	int x = -1, y = -1, z = -1, i = -1;  ///< field indices; i = -1 when there is no intensity

	std::size_t bytesPerPoint() const;
	std::size_t valuesPerPoint() const;
	std::size_t value(int field) const { return fields[field].value; }
	/// First element of `field` in the packed binary point at `p` (little-endian).
	double read(const char* p, int field) const;
};

/// Reads up to and including the DATA line; counts lines in lineNo. Throws InputError naming `path`.
PcdHeader readPcdHeader(std::istream& in, const std::string& path, std::size_t& lineNo);
}  // namespace vlo
