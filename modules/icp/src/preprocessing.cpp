#include <vlo/icp/preprocessing.h>

#include <unordered_set>

namespace vlo::icp
{
Points cropRange(const Points& points, double min_range, double max_range)
{
	Points kept;
	kept.reserve(points.size());
	const double min2 = min_range * min_range, max2 = max_range * max_range;
	for (const auto& p : points)
	{
		const double r2 = p.squaredNorm();
		if (std::isfinite(r2) && r2 > min2 && r2 < max2) kept.push_back(p);
	}
	return kept;
}

Points voxelDownsample(const Points& points, double voxel_size)
{
	std::unordered_set<Voxel, VoxelHasher> seen;
	seen.reserve(points.size());
	Points kept;
	kept.reserve(points.size());
	for (const auto& p : points)
		if (seen.insert(voxelOf(p, voxel_size)).second) kept.push_back(p);
	return kept;
}
}  // namespace vlo::icp
