#pragma once
// The local map: a hash of voxels, each holding a few points in the map frame. Bounded in two ways:
// at most max_points_per_voxel points per voxel (spread apart, so a voxel does not fill up with
// repeats of one surface patch), and no voxel farther than `radius` from the last sensor position.
#include <vlo/icp/voxel.h>

#include <Eigen/Geometry>
#include <limits>
#include <unordered_map>

namespace vlo::icp
{
class VoxelMap
{
   public:
	VoxelMap(double voxel_size, int max_points_per_voxel, double radius);

	/// Adds `points` (sensor frame) seen from `pose` (sensor in map), then drops the far voxels.
	void update(const Points& points, const Eigen::Isometry3d& pose);
	void addPoints(const Points& map_points);
	/// Drops every voxel whose first point is `radius` or more from `origin`.
	void removeFarFrom(const Eigen::Vector3d& origin);

	/// The map point closest to `q` among the 27 voxels around it and closer than sqrt(max_distance2);
	/// false when there is none.
	bool nearest(const Eigen::Vector3d& q, Eigen::Vector3d& closest, double& distance2,
		double max_distance2 = std::numeric_limits<double>::infinity()) const;

	bool empty() const { return voxels_.empty(); }
	std::size_t voxelCount() const { return voxels_.size(); }
	std::size_t pointCount() const;
	Points points() const;

   private:
	double voxel_size_, radius_, min_spacing2_;
	std::size_t max_points_;
	std::unordered_map<Voxel, Points, VoxelHasher> voxels_;
};
}  // namespace vlo::icp
