#include <vlo/loam/near_points.h>

#include <vlo/core/voxel_hash_map.h>

namespace vlo::loam
{
NearPoints::NearPoints(const std::vector<Eigen::Vector3f>& points, float radius)
	: radius_(radius), inv_(radius > 0 ? 1.0f / radius : 0.0f)
{
	if (radius <= 0) return;  // nothing is near
	for (const Eigen::Vector3f& p : points) cells_[voxelKey(cellOf(p, inv_))].push_back(p);
}

bool NearPoints::near(const Eigen::Vector3f& p) const
{
	if (cells_.empty()) return false;
	const Eigen::Vector3i c = cellOf(p, inv_);
	const float r2 = radius_ * radius_;
	for (int dx = -1; dx <= 1; ++dx)
		for (int dy = -1; dy <= 1; ++dy)
			for (int dz = -1; dz <= 1; ++dz)
			{
				const auto it = cells_.find(voxelKey(c + Eigen::Vector3i(dx, dy, dz)));
				if (it == cells_.end()) continue;
				for (const Eigen::Vector3f& q : it->second)
					if ((q - p).squaredNorm() <= r2) return true;
			}
	return false;
}
}  // namespace vlo::loam
