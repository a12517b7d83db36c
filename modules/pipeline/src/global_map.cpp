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

void GlobalMap::insert(const PointCloud& scan, const Eigen::Isometry3d& world_T_lidar, std::uint32_t anchor)
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
			{
				points_.push_back({batch[j].w.x(), batch[j].w.y(), batch[j].w.z(), batch[j].intensity});
				anchors_.push_back(anchor);
			}
	}
	while (points_.size() > max_points_) coarsen();
}

PointCloud GlobalMap::takePoints()
{
	occupied_ = VoxelHashMap();
	anchors_ = std::vector<std::uint32_t>();
	PointCloud out = std::move(points_);
	points_ = PointCloud();
	return out;
}

void GlobalMap::coarsen()
{
	leaf_ *= 2;
	thin();
}

void GlobalMap::thin()
{
	occupied_ = VoxelHashMap();
	std::size_t kept = 0;
	for (std::size_t i = 0; i < points_.size(); ++i)
		if (occupied_.insert(key({points_[i].x, points_[i].y, points_[i].z}), 0).second)
			points_[kept] = points_[i], anchors_[kept++] = anchors_[i];
	points_.resize(kept);
	points_.shrink_to_fit();
	anchors_.resize(kept);
	anchors_.shrink_to_fit();
}

void GlobalMap::correct(const std::vector<Eigen::Isometry3d>& correction_of_anchor)
{
	Eigen::Isometry3f C = Eigen::Isometry3f::Identity();
	std::uint32_t last = ~0u;  // the points of one scan come one after the other
	for (std::size_t i = 0; i < points_.size(); ++i)
	{
		if (anchors_[i] != last) last = anchors_[i], C = correction_of_anchor.at(last).cast<float>();
		auto& p = points_[i];
		const Eigen::Vector3f w = C * Eigen::Vector3f(p.x, p.y, p.z);
		p.x = w.x(), p.y = w.y(), p.z = w.z();
	}
	thin();
}
}  // namespace vlo::pipeline
