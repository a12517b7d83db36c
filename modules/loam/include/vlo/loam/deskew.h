#pragma once
// Motion compensation of a sweep: the sensor moves while it spins, so each return is expressed in
// the sensor frame at its own time. Under constant velocity over the sweep this moves every point
// into the frame at one reference time.
#include <vlo/loam/types.h>

#include <Eigen/Geometry>

namespace vlo::loam
{
/// `motion` is the pose of this frame in the previous one, `dt` seconds earlier; points at time
/// `time` (seconds from the frame's time, any sign) are moved into the frame at its time (0), along
/// the constant twist of `motion` (an arc in a turn).
void deskew(ScanPoints& points, const Eigen::Isometry3d& motion, double dt);

/// motion^a on SE(3), approximated like A-LOAM: rotation angle and translation both scaled by a (the
/// constant-velocity prior over a dropped frame).
Eigen::Isometry3d scaleMotion(const Eigen::Isometry3d& motion, double a);
}  // namespace vlo::loam
