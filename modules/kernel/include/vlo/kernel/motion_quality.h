#pragma once
// What a motion source knows of how far its motion of a frame can be trusted, for a LiDAR odometry
// that weighs the guess by it. Unknown values are NaN.
#include <limits>

namespace vlo::kernel
{
struct MotionQuality
{
	/// Image features the visual odometry tracked in its map for this motion (VisualOdometryStep::tracked).
	double tracked = std::numeric_limits<double>::quiet_NaN();
	/// Relative standard error of the motion's length, e.g. a scale corrector's of its estimate
	/// (ScaleCorrection::relative_error).
	double length_error = std::numeric_limits<double>::quiet_NaN();
};
}  // namespace vlo::kernel
