#pragma once
// sensor_msgs/PointCloud2 -> vlo scan: any field layout, point_step, row_step and byte order; x y z
// required; intensity, ring and per-point time optional, recognised by the names real drivers give them.
#include <vlo/io/lidar_observations.h>

#include <sensor_msgs/PointCloud2.h>

#include <string>

namespace vlo::rosbag_io
{
/// Points in the message's frame; time relative to msg.header.stamp; rings renumbered bottom-up
/// (orderRingsByElevation); non-finite points dropped and counted. Field names:
///  intensity: "intensity", else "reflectivity";  ring: "ring", else "line" (Livox);
///  time: "time" (s from the stamp, Velodyne), "t" (ns from the stamp, Ouster), "timestamp" (absolute s,
///  Hesai / Livox; values 1e9 times too large for seconds are read as ns).
/// Throws InputError(where, ...) for a missing x/y/z field or a layout that does not fit the data.
io::ScanReading decodePointCloud2(const sensor_msgs::PointCloud2& msg, const std::string& where);
}  // namespace vlo::rosbag_io
