#pragma once
// Motion compensation of a sweep: the sensor moves while it spins, so each return is expressed in
// the sensor frame at its own time. Under constant velocity over the sweep this moves every point
// into the frame at one reference time. Tabulated: exact transforms at 1024 time steps, blended per
// point in float (micrometres from exact), for speed over every feature of every pass. ICP's
// deskewExact and core's first-order moveToFrameTime follow the same constant twist but give other
// numbers, and every run's outputs stay byte-identical: three names, no merge.
#include <vlo/loam/types.h>

#include <Eigen/Geometry>

namespace vlo::loam
{
/// `motion` is the pose of this frame in the previous one, `dt` seconds earlier; points at time
/// `time` (seconds from the frame's time, any sign) are moved into the frame at its time (0), along
/// the constant twist of `motion` (an arc in a turn).
void deskewTabulated(ScanPoints& points, const Eigen::Isometry3d& motion, double dt);
}  // namespace vlo::loam
