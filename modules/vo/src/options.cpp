// [vo.orb], [vo.init], [vo.tracking], [vo.mapping]: every key with its type, range and help.
#include <vlo/vo/options.h>

namespace vlo::vo
{
void OrbOptions::declare(OptionTable& t)
{
	t.add("detector", detector, "anms | quadtree | opencv", "anms | quadtree (FAST spread over the image + rBRIEF) | opencv (cv::ORB as is)");
	t.add("n_features", n_features, ">= 50", "features per image over all levels");
	t.add("scale_factor", scale_factor, "(1, 2)", "scale between pyramid levels");
	t.add("n_levels", n_levels, "[1, 16]", "pyramid levels");
	t.add("fast_threshold", fast_threshold, "(0, 255)", "FAST threshold");
	t.add("fast_min_threshold", fast_min_threshold, "> 0", "FAST threshold in cells without a strong corner");
	t.add("edge_threshold", edge_threshold, "[19, 100)", "no feature closer to the border [px] (the ORB patch needs 19)");
	t.add("fallback_cell", fallback_cell, ">= 8", "cells [px] where fast_min_threshold may be used");
	t.add("anms_pool", anms_pool, ">= 1", "anms: strongest pool * wanted corners per level compete");
}

void OrbOptions::checkRelations() const
{
	require(fast_min_threshold <= fast_threshold, "fast_min_threshold", "must be <= fast_threshold");
}

void InitOptions::declare(OptionTable& t)
{
	t.add("min_features", min_features, ">= 8", "fewer: no initialisation from this frame");
	t.add("min_matches", min_matches, ">= 8", "fewer matches: the reference frame is replaced");
	t.add("search_radius", search_radius, "> 0", "matching window around the previous match [px]");
	t.add("match_ratio", match_ratio, "(0, 1]", "best/second best descriptor distance");
	t.add("max_level", max_level, ">= 0", "pyramid levels used for initialisation (0: finest only)");
	t.add("ransac_iterations", ransac_iterations, ">= 1", "for H and F each");
	t.add("sigma", sigma, "> 0", "keypoint noise at level 0 for the model scores [px]");
	t.add("homography_ratio", homography_ratio, "(0, 1)", "R_H = S_H/(S_H+S_F) above: homography");
	t.add("min_parallax_deg", min_parallax_deg, ">= 0", "parallax of the 50th best triangulated point [deg]");
	t.add("min_triangulated", min_triangulated, ">= 8", "triangulated points needed");
	t.add("min_good_fraction", min_good_fraction, "[0, 1]", "of the model inliers that must triangulate");
	t.add("ambiguity_ratio", ambiguity_ratio, "(0, 1]", "second best decomposition below ratio * best");
	t.add("planar_rotation_margin_deg", planar_rotation_margin_deg, ">= 0", "planar twofold ambiguity: the motion turning less by this [deg] wins; 0 = wait");
	t.add("ba_iterations", ba_iterations, ">= 0", "initial two-view bundle adjustment iterations");
	t.add("min_tracked_after_ba", min_tracked_after_ba, ">= 8", "map points needed after the initial BA");
	t.add("seed", seed, "any", "RANSAC seed");
}

void TrackingOptions::declare(OptionTable& t)
{
	t.add("descriptor_high", descriptor_high, "(0, 256]", "Hamming distance accepted by projection search");
	t.add("descriptor_low", descriptor_low, "> 0", "... by triangulation, fusion, keyframe search");
	t.add("check_orientation", check_orientation, "true | false", "rotation histogram consistency of matches");
	t.add("motion_radius", motion_radius, "> 0", "motion-model search window at level 0 [px]");
	t.add("min_motion_matches", min_motion_matches, ">= 0", "fewer: search again with twice the window");
	t.add("reference_radius", reference_radius, "> 0", "reference-keyframe fallback window [px]");
	t.add("reference_ratio", reference_ratio, "(0, 1]", "best/second best distance in that fallback");
	t.add("min_reference_matches", min_reference_matches, ">= 4", "matches needed by that fallback");
	t.add("min_pose_inliers", min_pose_inliers, ">= 4", "inliers needed after motion/reference tracking");
	t.add("local_radius", local_radius, "> 0", "factor on the local-map search window");
	t.add("local_ratio", local_ratio, "(0, 1]", "best/second best distance on the same level");
	t.add("max_local_keyframes", max_local_keyframes, ">= 1", "keyframes of the local map");
	t.add("min_local_inliers", min_local_inliers, ">= 4", "fewer after the local map: LOST (unless weak)");
	t.add("min_weak_inliers", min_weak_inliers, ">= 0", "fewer than min_local_inliers but this many: kept, a keyframe at once (0: off)");
	t.add("max_weak_frames", max_weak_frames, ">= 1", "weak frames kept in a row at most");
	t.add("pose_rounds", pose_rounds, ">= 1", "pose optimisation rounds (outliers re-marked)");
	t.add("pose_iterations", pose_iterations, ">= 1", "solver iterations per round");
	t.add("chi2", chi2, "> 0", "outlier threshold, squared error per sigma^2 (2 dof 95%)");
	t.add("min_frames_between_keyframes", min_frames_between_keyframes, ">= 0", "no keyframe sooner than this");
	t.add("keyframe_ref_ratio", keyframe_ref_ratio, "(0, 1]", "tracked < ratio * reference keyframe points: keyframe");
	t.add("keyframe_min_inliers", keyframe_min_inliers, ">= 0", "no keyframe from a frame with fewer inliers");
	t.add("keyframe_weak_inliers", keyframe_weak_inliers, ">= 0", "fewer inliers: keyframe whatever the ratio (0: off)");
	t.add("keyframe_interrupt_inliers", keyframe_interrupt_inliers, ">= 0",
		"fewer inliers and a keyframe needed: the pending local BA is applied now (0: off)");
	t.add("reinit_extrapolate", reinit_extrapolate, "true | false", "new map placed by constant velocity over the gap");
	t.add("reinit_keep_depth", reinit_keep_depth, "true | false", "new map scaled to the old map's median depth");
}

void TrackingOptions::checkRelations() const
{
	require(descriptor_low <= descriptor_high, "descriptor_low", "must be <= descriptor_high");
}

void MappingOptions::declare(OptionTable& t)
{
	t.add("triangulation_neighbours", triangulation_neighbours, ">= 1", "covisible keyframes searched for new points");
	t.add("min_baseline_ratio", min_baseline_ratio, ">= 0", "baseline/median depth below: pair skipped");
	t.add("min_depth_ratio", min_depth_ratio, "(0, 1)", "epipolar search from this fraction of the median depth");
	t.add("max_parallax_cos", max_parallax_cos, "(0, 1)", "rays closer to parallel are not triangulated");
	t.add("epipolar_chi2", epipolar_chi2, "> 0", "squared epipolar distance per sigma^2");
	t.add("scale_consistency", scale_consistency, ">= 1", "distance ratio vs scale ratio tolerance");
	t.add("fuse_neighbours", fuse_neighbours, ">= 0", "keyframes searched for duplicate points");
	t.add("fuse_radius", fuse_radius, "> 0", "fusion window per level scale [px]");
	t.add("min_found_ratio", min_found_ratio, "[0, 1)", "found/visible below: point culled");
	t.add("culling_min_observations", culling_min_observations, ">= 1", "at most this many observations later: culled");
	t.add("local_ba", local_ba, "true | false", "local bundle adjustment after each keyframe");
	t.add("ba_iterations", ba_iterations, ">= 0", "first local BA pass (Huber)");
	t.add("ba_refine_iterations", ba_refine_iterations, ">= 0", "second pass without outliers");
	t.add("max_ba_keyframes", max_ba_keyframes, ">= 2", "optimised keyframes in the local window");
	t.add("mapping_delay", mapping_delay, "[0, 3]", "keyframe k's local BA enters the map at frame k + this (0: inline); with one thread "
													"its robust pass runs at frame k + 1, its refine pass at k + this");
	t.add("min_covisibility", min_covisibility, ">= 1", "shared points for a covisibility edge");
	t.add("redundant_ratio", redundant_ratio, "(0, 1]", "keyframe culled when this fraction of its points ...");
	t.add("redundant_observers", redundant_observers, ">= 1", "... is seen by this many other keyframes");
	t.add("keep_keyframes", keep_keyframes, ">= 0", "older keyframes outside the local window dropped (0: none)");
}

std::vector<std::pair<std::string, OptionSet*>> VoOptions::parts()
{
	return {{"vo.orb", &orb}, {"vo.init", &init}, {"vo.tracking", &tracking}, {"vo.mapping", &mapping}};
}
}  // namespace vlo::vo
