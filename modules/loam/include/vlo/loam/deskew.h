#pragma once
// Motion compensation of a sweep: the sensor moves while it spins, so each return is expressed in
// the sensor frame at its own time. Under constant velocity over the sweep this moves every point
// into the frame at one reference time.
#include <vlo/loam/types.h>

#include <Eigen/Geometry>

namespace vlo::loam
{
/// `motion` is the pose of this sweep's frame in the previous sweep's frame (one sweep apart);
/// points at sweep time s (in sweeps; usually in [0, 1], any value allowed) are moved into the
/// frame at sweep time `reference`, along the constant twist of `motion` (an arc in a turn).
void deskew(ScanPoints& points, const Eigen::Isometry3d& motion, double reference);

/// motion^a on SE(3), approximated like A-LOAM: rotation angle and translation both scaled by a (the
/// constant-velocity prior over a dropped frame).
Eigen::Isometry3d scaleMotion(const Eigen::Isometry3d& motion, double a);
}  // namespace vlo::loam
