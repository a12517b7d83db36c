#pragma once
// Integer voxel coordinates of a point and their hash: the grid shared by downsampling and the map.
#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vlo::icp
{
using Points = std::vector<Eigen::Vector3d>;

struct Voxel
{
	int x = 0, y = 0, z = 0;
	bool operator==(const Voxel& o) const { return x == o.x && y == o.y && z == o.z; }
};

inline Voxel voxelOf(const Eigen::Vector3d& p, double size)
{
	return {static_cast<int>(std::floor(p.x() / size)), static_cast<int>(std::floor(p.y() / size)),
		static_cast<int>(std::floor(p.z() / size))};
}

/// The hash function of Voxel keys for std::unordered_map/set (core's VoxelHashMap is a map itself).
struct VoxelHasher
{
	std::size_t operator()(const Voxel& v) const
	{
		// Three large odd multipliers spread neighbouring cells over the buckets.
		const auto h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(v.x)) * 0x9E3779B185EBCA87ull ^
			static_cast<std::uint64_t>(static_cast<std::uint32_t>(v.y)) * 0xC2B2AE3D27D4EB4Full ^
			static_cast<std::uint64_t>(static_cast<std::uint32_t>(v.z)) * 0x165667B19E3779F9ull;
		return static_cast<std::size_t>(h ^ (h >> 29));
	}
};
}  // namespace vlo::icp
