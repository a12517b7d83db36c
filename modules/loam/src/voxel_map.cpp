#include <vlo/loam/voxel_map.h>

#include <algorithm>
#include <cmath>

namespace vlo::loam
{
VoxelMap::VoxelMap(double voxel_size, double resolution, int max_points_per_voxel)
	: size_(voxel_size),
	  resolution_(resolution),
	  inv_size_(static_cast<float>(1.0 / voxel_size)),
	  cells_per_axis_(std::max(1, static_cast<int>(std::ceil(voxel_size / resolution - 1e-9)))),
	  max_points_(max_points_per_voxel)
{
}

Eigen::Vector3i VoxelMap::voxelOf(const Eigen::Vector3f& p) const
{
	return cellOf(p, inv_size_);
}

std::size_t VoxelMap::insert(const std::vector<Eigen::Vector3f>& points, const std::vector<std::uint32_t>* tags)
{
	std::size_t added = 0;
	const float inv_res = static_cast<float>(1.0 / resolution_);
	for (std::size_t i = 0; i < points.size(); ++i)
	{
		const Eigen::Vector3f& p = points[i];
		const Eigen::Vector3i k = voxelOf(p);
		const std::uint32_t slot = free_.empty() ? static_cast<std::uint32_t>(voxels_.size()) : free_.back();
		const auto [id, is_new] = index_.insert(voxelKey(k), slot);
		if (is_new)
		{
			if (free_.empty()) voxels_.emplace_back();
			else free_.pop_back();
			voxels_[id].key = k;
		}
		Voxel& v = voxels_[id];
		if (static_cast<int>(v.points.size()) >= max_points_) continue;
		const Eigen::Vector3f local = p - k.cast<float>() * static_cast<float>(size_);
		const Eigen::Vector3i c = cellOf(local, inv_res).cwiseMax(0).cwiseMin(cells_per_axis_ - 1);
		const std::uint32_t cell = static_cast<std::uint32_t>(c.x() + cells_per_axis_ * (c.y() + cells_per_axis_ * c.z()));
		if (std::find(v.cells.begin(), v.cells.end(), cell) != v.cells.end()) continue;
		v.points.push_back(p);
		v.cells.push_back(cell);
		v.tags.push_back(tags ? (*tags)[i] : 0u);
		++added;
	}
	n_points_ += added;
	return added;
}

int VoxelMap::knn(const Eigen::Vector3f& q, int k, float max_dist, Eigen::Vector3f* out, std::uint32_t* out_tags) const
{
	constexpr int kMaxK = 32;
	float best_d2[kMaxK];
	std::pair<std::uint32_t, std::uint32_t> best_p[kMaxK];  ///< (voxel, index)
	k = std::min(k, kMaxK);
	int n = 0;
	const float max2 = max_dist * max_dist;

	// The 2x2x2 block of voxels whose shared corner is nearest to q, q's own voxel first. Per axis,
	// the neighbour is on the side q is nearer to, at distance gap[a] from q.
	const Eigen::Vector3f f = q * inv_size_;
	const Eigen::Vector3i base = cellOf(q, inv_size_);
	Eigen::Vector3i step;
	Eigen::Vector3f gap2;
	for (int a = 0; a < 3; ++a)
	{
		const float frac = f[a] - static_cast<float>(base[a]);
		step[a] = frac < 0.5f ? -1 : 1;
		const float g = (frac < 0.5f ? frac : 1.0f - frac) * static_cast<float>(size_);
		gap2[a] = g * g;
	}
	// A candidate must be closer than `limit`: max_dist, and once k are found the k-th best as well.
	float limit = max2;
	for (int o = 0; o < 8; ++o)
	{
		const int dx = o & 1, dy = (o >> 1) & 1, dz = (o >> 2) & 1;
		// Skip a neighbour voxel that cannot hold anything closer than the current k-th best.
		const float box2 = dx * gap2.x() + dy * gap2.y() + dz * gap2.z();
		if (box2 >= limit) continue;
		const std::uint32_t id = index_.find(voxelKey(base + Eigen::Vector3i(dx * step.x(), dy * step.y(), dz * step.z())));
		if (id == VoxelHashMap::kNone) continue;
		const Eigen::Vector3f* pts = voxels_[id].points.data();
		const auto m = static_cast<std::uint32_t>(voxels_[id].points.size());
		for (std::uint32_t j = 0; j < m; ++j)
		{
			const float d2 = (pts[j] - q).squaredNorm();
			if (d2 >= limit) continue;
			// Insertion into the sorted best list.
			int i = n < k ? n++ : n - 1;
			while (i > 0 && best_d2[i - 1] > d2)
			{
				best_d2[i] = best_d2[i - 1];
				best_p[i] = best_p[i - 1];
				--i;
			}
			best_d2[i] = d2;
			best_p[i] = {id, j};
			if (n == k) limit = std::min(max2, best_d2[k - 1]);
		}
	}
	for (int i = 0; i < n; ++i)
	{
		const Voxel& v = voxels_[best_p[i].first];
		out[i] = v.points[best_p[i].second];
		if (out_tags) out_tags[i] = v.tags[best_p[i].second];
	}
	return n;
}

std::size_t VoxelMap::removeFar(const Eigen::Vector3f& c, float radius)
{
	std::size_t removed = 0;
	const float r2 = radius * radius;
	const float half = static_cast<float>(0.5 * size_);
	std::vector<std::uint64_t> gone;
	index_.forEach([&](std::uint64_t key, std::uint32_t id) {
		Voxel& v = voxels_[id];
		const Eigen::Vector3f centre = v.key.cast<float>() * static_cast<float>(size_) + Eigen::Vector3f::Constant(half);
		if ((centre - c).squaredNorm() <= r2) return;
		removed += v.points.size();
		v.points = {};
		v.cells = {};
		v.tags = {};
		free_.push_back(id);
		gone.push_back(key);
	});
	for (std::uint64_t key : gone) index_.erase(key);
	n_points_ -= removed;
	return removed;
}

void VoxelMap::clear()
{
	index_.clear();
	voxels_.clear();
	free_.clear();
	n_points_ = 0;
}

void VoxelMap::appendPoints(std::vector<Eigen::Vector3f>& out) const
{
	out.reserve(out.size() + n_points_);
	index_.forEach([&](std::uint64_t, std::uint32_t id) { out.insert(out.end(), voxels_[id].points.begin(), voxels_[id].points.end()); });
}
}  // namespace vlo::loam
