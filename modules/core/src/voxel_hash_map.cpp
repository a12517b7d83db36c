#include <vlo/core/voxel_hash_map.h>

#include <algorithm>

namespace vlo
{
void VoxelHashMap::allocate(std::size_t capacity)
{
	std::size_t cap = 64;
	while (cap < capacity) cap *= 2;
	slots_.assign(cap, Slot{});
	mask_ = cap - 1;
	shift_ = 64;
	for (std::size_t c = cap; c > 1; c >>= 1) --shift_;
	size_ = 0;
}

void VoxelHashMap::grow()
{
	std::vector<Slot> old;
	old.swap(slots_);
	allocate(old.size() * 2);
	for (const Slot& s : old)
		if (s.key != kEmpty) insert(s.key, s.value);
}

void VoxelHashMap::reserve(std::size_t n) { allocate(2 * n + 1); }

std::pair<std::uint32_t, bool> VoxelHashMap::insert(std::uint64_t key, std::uint32_t value)
{
	if ((size_ + 1) * 2 > slots_.size()) grow();  // load factor <= 1/2 keeps probes short
	for (std::size_t i = slotOf(key);; i = (i + 1) & mask_)
	{
		Slot& s = slots_[i];
		if (s.key == key) return {s.value, false};
		if (s.key == kEmpty)
		{
			s.key = key;
			s.value = value;
			++size_;
			return {value, true};
		}
	}
}

// Backward-shift deletion: later entries of the probe run move up, so no tombstones are needed.
void VoxelHashMap::erase(std::uint64_t key)
{
	if (slots_.empty()) return;
	std::size_t i = slotOf(key);
	while (slots_[i].key != key)
	{
		if (slots_[i].key == kEmpty) return;
		i = (i + 1) & mask_;
	}
	for (std::size_t j = (i + 1) & mask_;; j = (j + 1) & mask_)
	{
		if (slots_[j].key == kEmpty) break;
		const std::size_t home = slotOf(slots_[j].key);
		// Move j into the hole at i unless its home lies cyclically in (i, j].
		const bool stays = (i <= j) ? (i < home && home <= j) : (i < home || home <= j);
		if (stays) continue;
		slots_[i] = slots_[j];
		i = j;
	}
	slots_[i] = Slot{};
	--size_;
}
}  // namespace vlo
