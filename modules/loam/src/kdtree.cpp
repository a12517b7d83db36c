#include <vlo/loam/kdtree.h>

#include <nanoflann.hpp>

namespace vlo::loam
{
namespace
{
struct Adaptor
{
	const ScanPoints* pts = nullptr;
	std::size_t kdtree_get_point_count() const { return pts ? pts->size() : 0; }
	float kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*pts)[i].p[static_cast<int>(dim)]; }
	template <class BBox>
	bool kdtree_get_bbox(BBox&) const
	{
		return false;
	}
};
using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Adaptor>, Adaptor, 3, int>;
}  // namespace

struct PointKdTree::Impl
{
	Adaptor adaptor;
	std::unique_ptr<Tree> tree;
};

PointKdTree::PointKdTree() : impl_(std::make_unique<Impl>()) {}
PointKdTree::~PointKdTree() = default;

void PointKdTree::build(const ScanPoints& points)
{
	impl_->adaptor.pts = &points;
	impl_->tree = std::make_unique<Tree>(3, impl_->adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10));
	if (!points.empty()) impl_->tree->buildIndex();
}

int PointKdTree::nearest(const Eigen::Vector3f& q, float* d2) const
{
	if (!impl_->tree || impl_->adaptor.kdtree_get_point_count() == 0) return -1;
	int idx = -1;
	float dist = 0;
	nanoflann::KNNResultSet<float, int> rs(1);
	rs.init(&idx, &dist);
	impl_->tree->findNeighbors(rs, q.data(), nanoflann::SearchParams());
	if (d2) *d2 = dist;
	return idx;
}
}  // namespace vlo::loam
