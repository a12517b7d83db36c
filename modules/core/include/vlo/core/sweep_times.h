#pragma once
// When each return of a spinning LiDAR's sweep was taken, from its azimuth: for scans whose sensor
// wrote no time per point (KITTI raw, most bags). The laser turns at a constant rate; at the frame's
// time it faces `frame_azimuth`, a fraction `frame_fraction` of the way through its turn (KITTI
// triggers its cameras as the laser faces forward, half-way: readme of the raw data). The sweep's
// seam, where the turn started and ended, lies behind that by `frame_fraction` of a turn.
#include <vlo/core/frame.h>

#include <Eigen/Geometry>

namespace vlo
{
struct SpinningSweep
{
	bool clockwise = true;  ///< seen from above: azimuth atan2(y, x) falls with time (Velodyne)
	double period = 0.1;  ///< seconds per turn
	double frame_azimuth = 0.0;  ///< [rad] where the laser faces at the frame's time (LiDAR frame)
	double frame_fraction = 0.5;  ///< where in the turn, in [0, 1], the frame's time falls

	/// Seconds from the frame's time at which the laser faced `azimuth` [rad], in
	/// [-frame_fraction, 1 - frame_fraction) * period.
	double timeAt(double azimuth) const;
};

/// Gives every point its time from its azimuth and marks the scan timed (has_time, time_from_azimuth).
void setTimesFromAzimuth(PointCloud& scan, const SpinningSweep& sweep);

/// The scan has times and they differ: something to deskew. A motion-compensated scan, or an exact
/// sensor's, has every time 0.
bool hasTimeSpread(const PointCloud& scan);

/// Moves every point to where it lay at the frame's time and sets its time to 0: `motion` is the
/// LiDAR's over `dt` seconds (this frame's pose in the previous one's), taken as a constant twist
/// xi, and a point taken `time` seconds from the frame's time moves by exp(time xi) to first order,
/// time (w x p + v) (0.1 mm at 12 m/s and 10 deg/s over 10 ms). Enough for the scale's depths;
/// ICP's deskewExact and LOAM's tabulated deskewTabulated are exact or within micrometres; each is
/// kept as it is so that outputs stay identical.
void moveToFrameTime(PointCloud& scan, const Eigen::Isometry3d& motion, double dt);
}  // namespace vlo
