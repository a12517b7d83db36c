#pragma once
// The vehicle's motion: world_T_vehicle at any time, so that sensors can be placed at the exact time
// of each image and of each LiDAR firing (motion distortion).
#include <vlo/io/trajectory.h>

#include <Eigen/Geometry>

namespace vlo::sim
{
class Rng;
class Road;

class VehicleMotion
{
   public:
	VehicleMotion() = default;
	/// `samples`: world_T_vehicle at increasing times.
	explicit VehicleMotion(Trajectory samples);
	/// Interpolated pose (slerp); beyond the ends the first/last velocity is extrapolated.
	Eigen::Isometry3d pose(double t) const;
	const Trajectory& samples() const { return samples_; }

   private:
	Trajectory samples_;
};

struct DriveStyle
{
	double v_min = 5, v_max = 14;  ///< m/s
	double a_max = 1.5;  ///< m/s^2, comfortable acceleration and braking
	double lateral_a_max = 2.5;  ///< m/s^2 in bends: speed is lowered before them
	double lane_offset = -1.75;  ///< m to the left of the centre line (right-hand traffic)
	/// false: the sharpest bend within 40 m sets the speed, never below v_min (gentle roads). true: every
	/// bend within 120 m, braking for it in time, down to bend_v_min (tight corners, U-turns).
	bool brake_for_bends = false;
	double bend_v_min = 2.5;  ///< m/s, with brake_for_bends
};

/// Planned distance of a drive of `duration` seconds (used to size the road before it exists).
double plannedDistance(const DriveStyle& style, double duration, uint64_t seed);

/// A drive along `road` starting at arc length s0: speeds between v_min and v_max that change every
/// few seconds with limited acceleration and jerk, slower in bends; a slight weave in the lane; pitch
/// from grade and braking, roll from cornering. Sampled every 10 ms over [0, duration].
VehicleMotion driveAlong(const Road& road, const DriveStyle& style, double s0, double duration, uint64_t seed);
}  // namespace vlo::sim
