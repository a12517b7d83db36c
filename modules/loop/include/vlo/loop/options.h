#pragma once
// Options of the loop closure, INI section [loop] (switched on by [pipeline] loop_closure).
#include <vlo/core/option_table.h>

namespace vlo::loop
{
struct LoopOptions : public OptionSet
{
	double keyframe_distance = 2.0;  ///< a new keyframe after the vehicle moved this far [m]
	double keyframe_angle_deg = 15.0;  ///< ... or turned this much [deg]

	// Place recognition (Scan Context).
	double descriptor_range = 80.0;  ///< [m] radius of the descriptor's rings
	int descriptor_rings = 20;
	int descriptor_sectors = 60;
	double sensor_height = 2.0;  ///< [m] added to heights so that the ground counts (Scan Context's LIDAR_HEIGHT)
	int candidates = 10;  ///< nearest ring keys whose full descriptors are compared
	double max_descriptor_distance = 0.25;  ///< larger distances are no candidate (0 = same, 1 = unrelated)
	double min_revisit_path = 50.0;  ///< [m] driven between two visits of a place, at least
	/// [m] each keyframe also queried from viewpoints this far to its left and right (a revisit in
	/// another lane; Scan Context's bins move with a lateral offset); 0 = off
	double query_shift = 3.5;

	// Geometric verification.
	double scan_voxel = 0.5;  ///< [m] keyframe scans are thinned to this voxel
	int submap_keyframes = 5;  ///< the candidate's submap: its keyframe and this many on each side
	double inlier_distance = 0.3;  ///< [m] a point registered within this of the submap's surface is an inlier
	double min_inlier_fraction = 0.6;  ///< fewer inliers: rejected
	/// Weakest direction of the registration over its strongest: less is degenerate (a corridor). The
	/// ground is always the strongest: true places give 0.06-0.26 (simulated KITTI 00 revisit, synthetic
	/// circuit), corridors 0.0003-0.005.
	double min_constraint = 0.02;
	double max_drift_per_metre = 0.1;  ///< the loop's correction must be within this times the path between the visits ...
	double max_drift_floor = 2.0;  ///< ... plus this [m], or it is rejected (repeated places)

	// Pose graph. Each frame's covariance is its registration's (the LiDAR odometry's information)
	// plus a per-metre floor, as the registration's J^T J is over-confident (doc/LOOP.md); a frame
	// without information gets the per-metre model alone.
	double odometry_floor_per_metre = 0.002;  ///< [m/m] translation floor added to a registration's covariance
	double odometry_floor_deg_per_metre = 0.01;  ///< [deg/m] rotation floor added to a registration's covariance
	double odometry_sigma_per_metre = 0.01;  ///< [m/m] translation noise of a frame without information
	double odometry_sigma_deg_per_metre = 0.05;  ///< [deg/m] rotation noise of a frame without information
	double loop_huber = 1.0;  ///< robust loss of loop edges, in sigmas

   protected:
	void declare(OptionTable& t) override;
};
}  // namespace vlo::loop
