#pragma once
// Voxel-grid downsampling: one point (the centroid) per occupied voxel of edge `leaf`.
#include <vlo/loam/types.h>

#include <vector>

namespace vlo::loam
{
/// Centroids in the order voxels are first hit.
std::vector<Eigen::Vector3f> voxelDownsample(const ScanPoints& points, float leaf);
}  // namespace vlo::loam
