#pragma once
// Scan preprocessing: range crop and voxel downsampling (one point per voxel).
#include <vlo/icp/voxel.h>

namespace vlo::icp
{
/// Keeps the finite points whose distance from the sensor is in (min_range, max_range).
Points cropRange(const Points& points, double min_range, double max_range);

/// Keeps the first point that falls in each voxel of edge `voxel_size`, in input order.
Points voxelDownsample(const Points& points, double voxel_size);
}  // namespace vlo::icp
