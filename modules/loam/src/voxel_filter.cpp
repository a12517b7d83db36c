#include <vlo/loam/voxel_filter.h>

#include <vlo/core/voxel_hash_map.h>

#include <cmath>

namespace vlo::loam
{
std::vector<Eigen::Vector3f> voxelDownsample(const ScanPoints& points, float leaf)
{
	std::vector<Eigen::Vector3f> sum;
	std::vector<int> count;
	VoxelHashMap slot;
	slot.reserve(points.size());
	const float inv = 1.0f / leaf;
	for (const ScanPoint& sp : points)
	{
		const Eigen::Vector3i k = cellOf(sp.p, inv);
		const auto [id, is_new] = slot.insert(voxelKey(k), static_cast<std::uint32_t>(sum.size()));
		if (is_new)
		{
			sum.push_back(sp.p);
			count.push_back(1);
		}
		else
		{
			sum[id] += sp.p;
			++count[id];
		}
	}
	for (std::size_t i = 0; i < sum.size(); ++i) sum[i] /= static_cast<float>(count[i]);
	return sum;
}
}  // namespace vlo::loam
