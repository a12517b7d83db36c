#pragma once
// Motion undistortion of a sweep under constant velocity. A point captured at `time` seconds from the
// frame's time lies in the sensor frame of its own instant; `motion` is the sensor's motion over the
// previous frame interval `dt` (pose of the current frame in the previous one). The point moves into
// the frame's own sensor frame by the fraction time / dt of that motion. The times are the scan's
// (the sensor's, or from the azimuth: [lidar] point_times); a scan without them is taken as it is.
// Exact, one SE(3) exponential per point in double, as KISS-ICP. LOAM's deskewTabulated (features
// only, blended between 1024 exact steps, in float: micrometres off) and core's moveToFrameTime
// (first order, for the scale's depths: 0.1 mm off) follow the same constant twist but give other
// numbers, and every run's outputs stay byte-identical: three names, no merge.
#include <vlo/core/frame.h>
#include <vlo/icp/voxel.h>

#include <Eigen/Geometry>

namespace vlo::icp
{
/// The scan's points in the sensor frame at the frame's time (as they are when its times do not differ).
Points deskewExact(const PointCloud& scan, const Eigen::Isometry3d& motion, double dt);
}  // namespace vlo::icp
