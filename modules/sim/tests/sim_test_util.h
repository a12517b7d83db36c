#pragma once
// Shared checks of the simulator tests.
#include <vlo/sim/world.h>

#include <Eigen/Core>

namespace vlo::sim::test
{
/// True if a surface of the world passes within `tol` of p along one of the six axis directions
/// (so p lies within tol of real geometry).
inline bool nearSurface(const World& w, const Eigen::Vector3d& p, double tol)
{
	for (int k = 0; k < 6; ++k)
	{
		Eigen::Vector3d axis = Eigen::Vector3d::Zero();
		axis[k / 2] = k % 2 ? 1 : -1;
		double r = -1;
		if (w.raycast(p - tol * axis, axis, 2 * tol, r)) return true;
	}
	return false;
}
}  // namespace vlo::sim::test
