#pragma once
// What both registrations produce and the solver consumes: source points paired with a line or a
// plane of the target. The pose T maps source points into the target frame.
#include <Eigen/Core>

#include <vector>

namespace vlo::loam
{
/// Source point p should lie on the line through a with unit direction u.
struct EdgeMatch
{
	Eigen::Vector3d p, a, u;
};

/// Source point p should lie on the plane n.x + d = 0 with |n| = 1.
struct PlaneMatch
{
	Eigen::Vector3d p, n;
	double d = 0;
};

struct Matches
{
	std::vector<EdgeMatch> edges;
	std::vector<PlaneMatch> planes;

	std::size_t size() const { return edges.size() + planes.size(); }
	void clear()
	{
		edges.clear();
		planes.clear();
	}
};
}  // namespace vlo::loam
