#pragma once
// The local map: points in a hash of cubic voxels around the vehicle.
// - Downsampled: each voxel is split into cells of `resolution` and keeps at most one point per
//   cell (the first seen), so revisiting a place adds nothing.
// - Bounded: voxels farther than a radius from the vehicle are dropped (removeFar), so the map
//   holds at most the volume of that ball, however long the drive.
// - Fast neighbour search without rebuilding a kd-tree each frame: the k nearest points within r
//   of q all lie in the 2x2x2 voxels nearest to q whenever r <= voxel_size / 2.
#include <vlo/core/voxel_hash_map.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vlo::loam
{
class VoxelMap
{
   public:
	VoxelMap(double voxel_size, double resolution, int max_points_per_voxel);

	/// Adds points (map frame) with an optional tag each (the scan line they come from); returns
	/// how many were kept.
	std::size_t insert(const std::vector<Eigen::Vector3f>& points, const std::vector<std::uint32_t>* tags = nullptr);
	/// Up to k (<= 32) nearest map points within max_dist of q, nearest first, and their tags;
	/// returns how many.
	int knn(const Eigen::Vector3f& q, int k, float max_dist, Eigen::Vector3f* out, std::uint32_t* out_tags = nullptr) const;
	/// Drops voxels whose centre is farther than radius from c; returns how many points went.
	std::size_t removeFar(const Eigen::Vector3f& c, float radius);
	void clear();
	/// Drops the points within radius of c for which gone(point) holds; returns how many went.
	/// (A template: the test runs for every map point near the vehicle each frame, inlined.)
	template <class Gone>
	std::size_t removeIf(const Eigen::Vector3f& c, float radius, Gone&& gone);

	std::size_t numPoints() const { return n_points_; }
	std::size_t numVoxels() const { return index_.size(); }
	void appendPoints(std::vector<Eigen::Vector3f>& out) const;

   private:
	struct Voxel
	{
		std::vector<Eigen::Vector3f> points;
		std::vector<std::uint32_t> cells;  ///< occupied cell of each point
		std::vector<std::uint32_t> tags;
		Eigen::Vector3i key = Eigen::Vector3i::Zero();
	};
	Eigen::Vector3i voxelOf(const Eigen::Vector3f& p) const;

	double size_, resolution_;
	float inv_size_;
	int cells_per_axis_, max_points_;
	VoxelHashMap index_;  ///< voxel key -> slot in voxels_
	std::vector<Voxel> voxels_;
	std::vector<std::uint32_t> free_;  ///< recycled slots
	std::size_t n_points_ = 0;
};

template <class Gone>
std::size_t VoxelMap::removeIf(const Eigen::Vector3f& c, float radius, Gone&& gone)
{
	std::size_t removed = 0;
	const float r2 = radius * radius;
	const float reach = radius + static_cast<float>(size_) * 0.87f;  // + half a voxel's diagonal
	const float half = static_cast<float>(0.5 * size_);
	// Slot by slot, not through the hash: the voxels are read in memory order and the next one's
	// points are fetched ahead (this runs over every voxel each frame, and waited on memory). Recycled
	// slots hold no points.
	for (std::size_t id = 0; id < voxels_.size(); ++id)
	{
		if (id + 1 < voxels_.size()) __builtin_prefetch(voxels_[id + 1].points.data());
		Voxel& v = voxels_[id];
		const Eigen::Vector3f centre = v.key.cast<float>() * static_cast<float>(size_) + Eigen::Vector3f::Constant(half);
		if (v.points.empty() || (centre - c).squaredNorm() > reach * reach) continue;
		for (std::size_t i = 0; i < v.points.size();)
		{
			if ((v.points[i] - c).squaredNorm() > r2 || !gone(v.points[i]))
			{
				++i;
				continue;
			}
			// Swap-remove: the order within a voxel does not matter; the cell is free again.
			v.points[i] = v.points.back(), v.points.pop_back();
			v.cells[i] = v.cells.back(), v.cells.pop_back();
			v.tags[i] = v.tags.back(), v.tags.pop_back();
			++removed;
		}
	}
	n_points_ -= removed;
	return removed;
}
}  // namespace vlo::loam
