#pragma once
// What became of one scan in a LiDAR odometry (LOAM's or ICP's): one enum for both, so that the
// frames.csv column lo_status means the same whichever runs.
namespace vlo
{
enum class LidarFrameStatus
{
	Ok,  ///< the enabled registrations succeeded
	Initialized,  ///< first usable scan: the map starts here
	Degraded,  ///< a registration failed (reason says why): pose from another stage or the prior (LOAM)
	Skipped,  ///< unusable input or too few correspondences (reason says why): pose from the prediction
};

/// "ok", "initialized", "degraded", "skipped".
const char* toString(LidarFrameStatus s);
}  // namespace vlo
