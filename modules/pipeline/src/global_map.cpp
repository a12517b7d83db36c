#include <vlo/pipeline/global_map.h>

#include <cmath>

namespace vlo
{
void GlobalMap::insert(const PointCloud& scan, const Eigen::Isometry3d& world_T_lidar)
{
	const Eigen::Isometry3f T = world_T_lidar.cast<float>();
	const float r2 = static_cast<float>(max_range_ * max_range_);
	// 21 bits per axis: +-200 km at 0.2 m voxels.
	const auto cell = [&](float v) {
		return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / leaf_)) & 0x1FFFFF);
	};
	for (const auto& p : scan)
	{
		const Eigen::Vector3f s(p.x, p.y, p.z);
		if (s.squaredNorm() > r2) continue;
		const Eigen::Vector3f w = T * s;
		const std::uint64_t key = (cell(w.x()) << 42) | (cell(w.y()) << 21) | cell(w.z());
		if (occupied_.insert(key).second) points_.push_back({w.x(), w.y(), w.z(), p.intensity});
	}
}
}  // namespace vlo
