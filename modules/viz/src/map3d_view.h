#pragma once
// Internal: the camera drawMap3D renders with, exposed so that tests can find what it drew.
#include <vlo/viz/map3d.h>

#include "view_fit.h"

namespace vlo::viz
{
/// The view that frames `map` and the trajectories for `style`. Throws InputError when there is nothing to draw.
ViewCamera map3DView(const PointCloud& map, const std::vector<NamedTrajectory>& trajs, const Trajectory* gt,
	const Map3DStyle& style = {});
}  // namespace vlo::viz
