#pragma once
// Nearest-neighbour search over a point set (nanoflann kd-tree, hidden behind this small API).
#include <vlo/loam/types.h>

#include <memory>

namespace vlo::loam
{
class PointKdTree
{
   public:
	PointKdTree();
	~PointKdTree();
	PointKdTree(const PointKdTree&) = delete;
	PointKdTree& operator=(const PointKdTree&) = delete;

	/// Indexes `points`, which must stay alive and unchanged while the tree is used.
	void build(const ScanPoints& points);
	/// Index of the point closest to q and its squared distance; -1 when the set is empty.
	int nearest(const Eigen::Vector3f& q, float* d2) const;

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};
}  // namespace vlo::loam
