#pragma once
// A small open-addressing hash map from voxel coordinates to a 32-bit value, for LOAM's map and
// voxel filter and the run's map.pcd: linear probing in one flat array, several times faster than std::unordered_map
// for these lookups (no node per entry, one cache line per probe).
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vlo
{
/// floor() for the voxel indices: std::floor is a library call on baseline x86-64 (no SSE4.1).
inline int fastFloor(float x)
{
	const int i = static_cast<int>(x);
	return i - (x < static_cast<float>(i) ? 1 : 0);
}

/// Integer coordinates of the cell of edge 1/inv_size that holds p.
inline Eigen::Vector3i cellOf(const Eigen::Vector3f& p, float inv_size)
{
	return Eigen::Vector3i(fastFloor(p.x() * inv_size), fastFloor(p.y() * inv_size), fastFloor(p.z() * inv_size));
}

/// Packs integer voxel coordinates (21 bits each: +-1e6 voxels) into one key.
inline std::uint64_t voxelKey(const Eigen::Vector3i& k)
{
	const auto u = [](int v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1FFFFFu; };
	return (u(k.x()) << 42) | (u(k.y()) << 21) | u(k.z());
}

class VoxelHashMap
{
   public:
	static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

	/// Value of key, or kNone.
	std::uint32_t find(std::uint64_t key) const
	{
		if (slots_.empty()) return kNone;
		for (std::size_t i = slotOf(key);; i = (i + 1) & mask_)
		{
			const Slot& s = slots_[i];
			if (s.key == key) return s.value;
			if (s.key == kEmpty) return kNone;
		}
	}
	/// Asks the CPU to fetch key's home slot, ahead of a lookup of it.
	void prefetch(std::uint64_t key) const
	{
		if (!slots_.empty()) __builtin_prefetch(&slots_[slotOf(key)]);
	}
	/// Inserts (key, value) unless key is present; returns the stored value and whether it is new.
	std::pair<std::uint32_t, bool> insert(std::uint64_t key, std::uint32_t value);
	/// Removes key if present.
	void erase(std::uint64_t key);
	void clear()
	{
		slots_.clear();
		size_ = 0;
		mask_ = 0;
	}
	/// Empties the table and sizes it for n entries without growing.
	void reserve(std::size_t n);
	std::size_t size() const { return size_; }

	/// Calls f(key, value) for every entry.
	template <class F>
	void forEach(F&& f) const
	{
		for (const Slot& s : slots_)
			if (s.key != kEmpty) f(s.key, s.value);
	}

   private:
	static constexpr std::uint64_t kEmpty = ~0ull;  ///< no valid key has all 64 bits set
	struct Slot
	{
		std::uint64_t key = kEmpty;
		std::uint32_t value = 0;
	};
	std::size_t slotOf(std::uint64_t key) const { return (key * 0x9E3779B97F4A7C15ull) >> shift_; }
	void grow();
	void allocate(std::size_t capacity);

	std::vector<Slot> slots_;
	std::size_t size_ = 0, mask_ = 0;
	int shift_ = 64;
};
}  // namespace vlo
