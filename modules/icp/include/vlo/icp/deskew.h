#pragma once
// Motion undistortion of a sweep under constant velocity. A point captured at `time` seconds from the
// frame's time lies in the sensor frame of its own instant; `motion` is the sensor's motion over the
// previous frame interval `dt` (pose of the current frame in the previous one). The point moves into
// the frame's own sensor frame by the fraction time / dt of that motion.
//
// Times: LidarPoint::time when the scan has_time. Otherwise, on request, KISS-ICP's rule from the
// azimuth phi = atan2(y, x): the sweep starts and ends behind the sensor and spins clockwise seen from
// above, so the sweep fraction is s = (1 - phi / pi) / 2 in [0, 1]; the frame's pose refers to the
// middle of the sweep (the forward firing, where KITTI triggers its camera), so the time is
// (s - 0.5) * dt = -phi / (2 pi) * dt.
#include <vlo/core/frame.h>
#include <vlo/icp/voxel.h>

#include <Eigen/Geometry>

namespace vlo::icp
{
enum class SweepTimes
{
	None,  ///< no deskew: points taken as they are
	PerPoint,  ///< LidarPoint::time
	Azimuth,  ///< KISS-ICP's rule from the azimuth
};
const char* toString(SweepTimes t);

/// The fraction `s` of a constant-velocity (constant twist) motion; s may be negative or above 1.
Eigen::Isometry3d scaleMotion(const Eigen::Isometry3d& motion, double s);

/// Capture time of a point from its azimuth, in seconds from the frame's time (see above).
double azimuthTime(const LidarPoint& p, double dt);

/// The scan's points in the sensor frame at the frame's time.
Points deskew(const PointCloud& scan, SweepTimes times, const Eigen::Isometry3d& motion, double dt);
}  // namespace vlo::icp
