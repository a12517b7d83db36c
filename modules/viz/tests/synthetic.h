#pragma once
// Realistic synthetic inputs for the snapshot tests and examples: a curved ~1 km drive with drifting
// estimates, a street-like point-cloud map around it, and a camera+LiDAR frame of a small street.
#include <vlo/core/frame.h>
#include <vlo/io/trajectory.h>

#include <mrpt/img/CImage.h>

namespace vlo::viz::synth
{
/// Ground truth: ~length metres at 5-14 m/s, 10 Hz, two 90-degree turns, gentle slopes; starts at identity.
Trajectory curvedDrive(double length);
/// Re-integrates the relative motions of `gt` with a scale error growing to `scaleDrift` at the end,
/// a yaw bias (rad per metre) and noise: what a drifting odometry produces.
Trajectory driftingEstimate(const Trajectory& gt, double scaleDrift, double yawPerMetre, double noise, unsigned seed);
/// Street around the drive (world frame; the vehicle origin is 1.73 m above the road): road, facades,
/// parked cars, poles and trees. About 250 points per metre of road.
PointCloud streetMap(const Trajectory& gt, unsigned seed);

/// A small street seen by a KITTI-like rig: grayscale 1241x376 image, HDL-64-like scan (LiDAR frame).
struct CameraLidarFrame
{
	mrpt::img::CImage image;
	PointCloud scan;
	SensorRig rig;
};
CameraLidarFrame streetFrame(unsigned seed);
/// KITTI-like rig: camera 1.65 m and LiDAR 1.73 m above the ground (vehicle frame on the road).
SensorRig kittiLikeRig();
}  // namespace vlo::viz::synth
