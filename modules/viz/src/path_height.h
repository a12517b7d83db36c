#pragma once
// Internal: height of map points above the nearest pose of a path (horizontal distance), so that the
// colour of a point says "road", "car", "facade" even where the road climbs or the first frame tilts.
#include <vlo/core/frame.h>
#include <vlo/io/trajectory.h>

#include <vector>

namespace vlo::viz
{
/// z of each point minus z of the horizontally nearest pose of `path`; points farther than
/// `radius` metres from every pose are compared with the path's median z instead.
std::vector<float> heightAbovePath(const PointCloud& pts, const Trajectory& path, double radius = 40);
}  // namespace vlo::viz
