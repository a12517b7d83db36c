#pragma once
// The map a run writes to map.pcd: scans registered with the final poses, thinned to one point per
// voxel. Unlike LOAM's bounded local map it covers the whole drive.
#include <vlo/core/frame.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <unordered_set>

namespace vlo
{
class GlobalMap
{
   public:
	/// leaf: voxel edge [m] (> 0); max_range: scan points farther from the sensor are not added.
	GlobalMap(double leaf, double max_range) : leaf_(leaf), max_range_(max_range) {}

	/// Adds the scan (LiDAR frame) seen from world_T_lidar; keeps the first point of each voxel.
	void insert(const PointCloud& scan, const Eigen::Isometry3d& world_T_lidar);
	const PointCloud& points() const { return points_; }

   private:
	double leaf_, max_range_;
	std::unordered_set<std::uint64_t> occupied_;
	PointCloud points_;
};
}  // namespace vlo
