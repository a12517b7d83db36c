#include <vlo/pipeline/global_map.h>

#include <array>
#include <cmath>

namespace vlo::pipeline
{
std::uint64_t GlobalMap::key(const Eigen::Vector3f& w) const
{
	const float leaf = static_cast<float>(leaf_);
	return voxelKey(Eigen::Vector3i(fastFloor(w.x() / leaf), fastFloor(w.y() / leaf), fastFloor(w.z() / leaf)));
}

void GlobalMap::insert(const PointCloud& scan, const Eigen::Isometry3d& world_T_lidar)
{
	const Eigen::Isometry3f T = world_T_lidar.cast<float>();
	const float r2 = static_cast<float>(max_range_ * max_range_);
	std::uint64_t last = ~0ull;  // consecutive returns often share a voxel: one lookup for the run
	// In batches: the keys of a batch first, their slots prefetched, then the lookups (the set
	// outgrows the caches, and a lookup that waits for memory is most of this function's time).
	constexpr std::size_t kBatch = 32;
	struct Pending
	{
		std::uint64_t key;
		Eigen::Vector3f w;
		float intensity;
	};
	std::array<Pending, kBatch> batch;
	for (std::size_t i = 0; i < scan.size();)
	{
		std::size_t n = 0;
		for (; i < scan.size() && n < kBatch; ++i)
		{
			const LidarPoint& p = scan[i];
			const Eigen::Vector3f s(p.x, p.y, p.z);
			if (s.squaredNorm() > r2) continue;
			const Eigen::Vector3f w = T * s;
			const std::uint64_t k = key(w);
			if (k == last) continue;
			last = k;
			occupied_.prefetch(k);
			batch[n++] = {k, w, p.intensity};
		}
		for (std::size_t j = 0; j < n; ++j)
			if (occupied_.insert(batch[j].key, 0).second)
				points_.push_back({batch[j].w.x(), batch[j].w.y(), batch[j].w.z(), batch[j].intensity});
	}
	while (points_.size() > max_points_) coarsen();
}

PointCloud GlobalMap::takePoints()
{
	occupied_ = VoxelHashMap();
	PointCloud out = std::move(points_);
	points_ = PointCloud();
	return out;
}

void GlobalMap::coarsen()
{
	leaf_ *= 2;
	occupied_ = VoxelHashMap();
	std::size_t kept = 0;
	for (const auto& p : points_)
		if (occupied_.insert(key({p.x, p.y, p.z}), 0).second) points_[kept++] = p;
	points_.resize(kept);
	points_.shrink_to_fit();
}
}  // namespace vlo::pipeline
