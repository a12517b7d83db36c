#pragma once
// A spinning LiDAR's beams are calibrated per laser; an error common to the elevations tilts every ray
// up or down ([lidar] elevation_offset_deg corrects it for every consumer of the scan). The ground then
// looks like a shallow bowl about the sensor, which a LiDAR odometry turns into a pitch drift as it
// moves (KITTI raw 0013: 0.5 deg over 45 m). In the scale corrector a ray 0.2 degrees too steep
// projects its point 2.5 px too low in the image (f = 718 px), where the ground the camera sees at
// that pixel is nearer than the point's depth by 2 % at 10 m, so s_j = d_j / v_j comes out too large.
// KITTI's HDL-64 scans are known to need +0.22 degrees (IMLS-SLAM, Deschaud 2018; CT-ICP).
#include <vlo/core/frame.h>

namespace vlo
{
/// Turns every ray of `scan` up by `offset_deg` about the horizontal axis across it (LiDAR frame, z up),
/// in place: the range and the azimuth stay, the elevation grows by the offset.
void raiseElevations(PointCloud& scan, double offset_deg);
}  // namespace vlo
