#pragma once
// The map a run writes to map.pcd: scans registered with the final poses, thinned to one point per
// voxel. Unlike LOAM's bounded local map it covers the whole drive, so it has a budget of points:
// past it the voxels double in size and the map is thinned again, and memory stays bounded however
// long the drive (a 5 km drive gets a coarser map.pcd than a 500 m one; doc/ROBUSTNESS.md).
#include <vlo/core/frame.h>
#include <vlo/core/voxel_hash_map.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace vlo::pipeline
{
class GlobalMap
{
   public:
	/// 200-320 MB with the voxel index (16 bytes a point, 32-64 in the at most half-full hash); a
	/// 400 m urban drive holds about 1M at 0.2 m.
	static constexpr std::size_t kDefaultMaxPoints = 4'000'000;

	/// leaf: voxel edge [m] (> 0); max_range: scan points farther from the sensor are not added.
	GlobalMap(double leaf, double max_range, std::size_t max_points = kDefaultMaxPoints)
		: leaf_(leaf), max_range_(max_range), max_points_(max_points)
	{
	}

	/// Adds the scan (LiDAR frame) seen from world_T_lidar; keeps the first point of each voxel. Each
	/// point kept remembers `anchor` (the run's row of the scan), for correct().
	void insert(const PointCloud& scan, const Eigen::Isometry3d& world_T_lidar, std::uint32_t anchor = 0);
	/// Moves each point by the correction of its anchor (world_corrected_T_world, e.g. from loop
	/// closure), then keeps the first point of each voxel again: two visits of a place that the
	/// correction brings together leave one copy. In place: no second map at the end of a long run.
	void correct(const std::vector<Eigen::Isometry3d>& correction_of_anchor);
	const PointCloud& points() const { return points_; }
	/// Hands the points over and frees the voxel index: the map is done (end of a run). A copy would
	/// double the memory of the largest structure of a long run just when the outputs need some.
	PointCloud takePoints();
	/// The voxel edge now: the one asked for, doubled each time the budget was reached.
	double leaf() const { return leaf_; }

   private:
	std::uint64_t key(const Eigen::Vector3f& w) const;
	/// Doubles the voxel and keeps the first point of each new voxel, in the order they came.
	void coarsen();
	/// Keeps the first point of each voxel of the current size, in the order they came.
	void thin();

	double leaf_, max_range_;
	std::size_t max_points_;
	VoxelHashMap occupied_;  ///< voxel key -> nothing (a set)
	PointCloud points_;
	std::vector<std::uint32_t> anchors_;  ///< one per point
};
}  // namespace vlo::pipeline
