#pragma once
// Internal: the header of a PCD v0.7 file, checked strictly before PCL reads the file (PCL's reader trusts
// its header: a corrupt one can make it read out of bounds).
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace vlo::io
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
	bool compressed = false;  ///< binary_compressed (LZF)
	int x = -1, y = -1, z = -1, i = -1;  ///< field indices; i = -1 when there is no intensity

	std::size_t bytesPerPoint() const;
};

/// Reads up to and including the DATA line; counts lines in lineNo. Throws InputError naming `path`.
PcdHeader readPcdHeader(std::istream& in, const std::string& path, std::size_t& lineNo);
}  // namespace vlo::io
