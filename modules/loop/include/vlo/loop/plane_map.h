#pragma once
// The candidate's submap for the point-to-plane registration: its points in a kd-tree (nanoflann) and
// each point's surface normal, estimated from its neighbours the first time a scan point pairs with it.
#include <vlo/icp/voxel.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace vlo::loop
{
class PlaneMap
{
   public:
	explicit PlaneMap(icp::Points points);
	~PlaneMap();
	PlaneMap(const PlaneMap&) = delete;
	PlaneMap& operator=(const PlaneMap&) = delete;

	/// The index of the map point nearest to q and its squared distance; false when the map is empty.
	bool nearest(const Eigen::Vector3d& q, std::size_t& index, double& distance2) const;
	/// The unit normal of the surface around point `index`; false where the neighbours are no plane.
	bool normal(std::size_t index, Eigen::Vector3d& n) const;
	const Eigen::Vector3d& point(std::size_t index) const { return points_[index]; }
	std::size_t size() const { return points_.size(); }

   private:
	struct Tree;
	icp::Points points_;
	std::unique_ptr<Tree> tree_;
	// 0 = not yet estimated, 1 = a plane, 2 = no plane (the cache is filled by const queries).
	mutable std::vector<unsigned char> state_;
	mutable std::vector<Eigen::Vector3d> normals_;
};
}  // namespace vlo::loop
