// [loop]: every key with its range and help in one declaration list.
#include <vlo/loop/options.h>

namespace vlo::loop
{
void LoopOptions::declare(OptionTable& t)
{
	t.add("keyframe_distance", keyframe_distance, "> 0", "a new keyframe after moving this far [m]");
	t.add("keyframe_angle_deg", keyframe_angle_deg, "> 0", "... or turning this much [deg]");
	t.add("descriptor_range", descriptor_range, "> 0", "radius of the Scan Context rings [m]");
	t.add("descriptor_rings", descriptor_rings, ">= 2", "rings of the Scan Context");
	t.add("descriptor_sectors", descriptor_sectors, ">= 4", "sectors of the Scan Context");
	t.add("sensor_height", sensor_height, ">= 0", "added to point heights so that the ground counts [m]");
	t.add("candidates", candidates, ">= 1", "nearest ring keys whose descriptors are compared");
	t.add("max_descriptor_distance", max_descriptor_distance, "(0, 1]", "larger descriptor distances are no candidate");
	t.add("min_revisit_path", min_revisit_path, ">= 0", "path driven between two visits of a place, at least [m]");
	t.add("query_shift", query_shift, ">= 0", "each keyframe also queried from this far to its left and right (another lane); 0 = off [m]");
	t.add("scan_voxel", scan_voxel, "> 0", "keyframe scans are thinned to this voxel [m]");
	t.add("submap_keyframes", submap_keyframes, ">= 0", "keyframes on each side of the candidate in its submap");
	t.add("inlier_distance", inlier_distance, "> 0", "a registered point within this of the submap's surface is an inlier [m]");
	t.add("min_inlier_fraction", min_inlier_fraction, "(0, 1]", "fewer inliers: the loop is rejected");
	t.add("min_constraint", min_constraint, "[0, 1]", "weakest over strongest direction of the registration: less is degenerate");
	t.add("max_drift_per_metre", max_drift_per_metre, ">= 0", "a loop's correction must be within this times the path between the visits ...");
	t.add("max_drift_floor", max_drift_floor, ">= 0", "... plus this [m]");
	t.add("odometry_floor_per_metre", odometry_floor_per_metre, ">= 0", "translation noise per metre added to each frame's registration covariance (a floor) [m/m]");
	t.add("odometry_floor_deg_per_metre", odometry_floor_deg_per_metre, ">= 0", "... and rotation noise [deg/m]");
	t.add("odometry_sigma_per_metre", odometry_sigma_per_metre, "> 0", "translation noise per metre of a frame without registration information [m/m]");
	t.add("odometry_sigma_deg_per_metre", odometry_sigma_deg_per_metre, "> 0", "... and rotation noise [deg/m]");
	t.add("loop_huber", loop_huber, "> 0", "robust (Huber) loss of loop edges [sigmas]");
}
}  // namespace vlo::loop
