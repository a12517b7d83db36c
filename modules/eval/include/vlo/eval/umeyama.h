#pragma once
// Closed-form least-squares alignment of two point sets (Umeyama, PAMI 1991).
#include <vlo/core/se3.h>

#include <Eigen/Core>
#include <vector>

namespace vlo::eval
{
/// The S minimising sum_i ||dst_i - S * src_i||^2, a similarity when with_scale, else rigid (s = 1).
/// Sizes must match and be >= 1 (std::invalid_argument otherwise). When the points are collinear the
/// rotation about their line is free; the smallest rotation is returned, so identical straight
/// trajectories align with the identity. With scale and src all at one point, throws InputError.
Sim3 umeyama(const std::vector<Eigen::Vector3d>& src, const std::vector<Eigen::Vector3d>& dst, bool with_scale);
}  // namespace vlo::eval
