// The open-addressing voxel hash against std::unordered_map under inserts and erasures.
#include <gtest/gtest.h>
#include <vlo/core/voxel_hash_map.h>

#include <random>
#include <unordered_map>

namespace vlo::test
{
TEST(VoxelHashMap, MatchesUnorderedMap)
{
	std::mt19937 rng(1);
	std::uniform_int_distribution<int> coord(-40, 40);
	VoxelHashMap h;
	std::unordered_map<std::uint64_t, std::uint32_t> ref;
	for (int i = 0; i < 20000; ++i)
	{
		const std::uint64_t key = voxelKey(Eigen::Vector3i(coord(rng), coord(rng), coord(rng) / 8));
		if (i % 3 == 2)
		{
			h.erase(key);
			ref.erase(key);
		}
		else
		{
			const auto [v, is_new] = h.insert(key, static_cast<std::uint32_t>(i));
			const auto r = ref.try_emplace(key, static_cast<std::uint32_t>(i));
			ASSERT_EQ(is_new, r.second);
			ASSERT_EQ(v, r.first->second);
		}
	}
	ASSERT_EQ(h.size(), ref.size());
	for (const auto& [k, v] : ref) ASSERT_EQ(h.find(k), v);
	std::size_t n = 0;
	h.forEach([&](std::uint64_t k, std::uint32_t v) {
		EXPECT_EQ(ref.at(k), v);
		++n;
	});
	EXPECT_EQ(n, ref.size());
	EXPECT_EQ(h.find(voxelKey(Eigen::Vector3i(1000, 0, 0))), VoxelHashMap::kNone);
}
}  // namespace vlo::test
