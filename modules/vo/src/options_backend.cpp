// [vo.tracking], [vo.mapping] and the aggregate of all sections.
#include <mrpt/config/CConfigFileBase.h>
#include <vlo/vo/options.h>

#include "option_checks.h"

namespace vlo::vo
{
using detail::require;

void TrackingOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	VLO_VO_LOAD(descriptor_high, int);
	VLO_VO_LOAD(descriptor_low, int);
	VLO_VO_LOAD(check_orientation, bool);
	VLO_VO_LOAD(motion_radius, double);
	VLO_VO_LOAD(min_motion_matches, int);
	VLO_VO_LOAD(reference_radius, double);
	VLO_VO_LOAD(reference_ratio, double);
	VLO_VO_LOAD(min_reference_matches, int);
	VLO_VO_LOAD(min_pose_inliers, int);
	VLO_VO_LOAD(local_radius, double);
	VLO_VO_LOAD(local_ratio, double);
	VLO_VO_LOAD(max_local_keyframes, int);
	VLO_VO_LOAD(min_local_inliers, int);
	VLO_VO_LOAD(pose_rounds, int);
	VLO_VO_LOAD(pose_iterations, int);
	VLO_VO_LOAD(chi2, double);
	VLO_VO_LOAD(min_frames_between_keyframes, int);
	VLO_VO_LOAD(keyframe_ref_ratio, double);
	VLO_VO_LOAD(keyframe_min_inliers, int);
	VLO_VO_LOAD(reinit_extrapolate, bool);
	VLO_VO_LOAD(reinit_keep_depth, bool);
}

void TrackingOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(descriptor_high, "Hamming distance accepted by projection search");
	MRPT_SAVE_CONFIG_VAR_COMMENT(descriptor_low, "... by triangulation, fusion, keyframe search");
	MRPT_SAVE_CONFIG_VAR_COMMENT(check_orientation, "rotation histogram consistency of matches");
	MRPT_SAVE_CONFIG_VAR_COMMENT(motion_radius, "motion-model search window at level 0 [px]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_motion_matches, "fewer: search again with twice the window");
	MRPT_SAVE_CONFIG_VAR_COMMENT(reference_radius, "reference-keyframe fallback window [px]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(reference_ratio, "best/second best distance in that fallback");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_reference_matches, "matches needed by that fallback");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_pose_inliers, "inliers needed after motion/reference tracking");
	MRPT_SAVE_CONFIG_VAR_COMMENT(local_radius, "factor on the local-map search window");
	MRPT_SAVE_CONFIG_VAR_COMMENT(local_ratio, "best/second best distance on the same level");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_local_keyframes, "keyframes of the local map");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_local_inliers, "fewer after the local map: LOST");
	MRPT_SAVE_CONFIG_VAR_COMMENT(pose_rounds, "pose optimisation rounds (outliers re-marked)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(pose_iterations, "Ceres iterations per round");
	MRPT_SAVE_CONFIG_VAR_COMMENT(chi2, "outlier threshold, squared error per sigma^2 (2 dof 95%)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_frames_between_keyframes, "no keyframe sooner than this");
	MRPT_SAVE_CONFIG_VAR_COMMENT(keyframe_ref_ratio, "tracked < ratio * reference keyframe points: keyframe");
	MRPT_SAVE_CONFIG_VAR_COMMENT(keyframe_min_inliers, "no keyframe from a frame with fewer inliers");
	MRPT_SAVE_CONFIG_VAR_COMMENT(reinit_extrapolate, "new map placed by constant velocity over the gap");
	MRPT_SAVE_CONFIG_VAR_COMMENT(reinit_keep_depth, "new map scaled to the old map's median depth");
}

void TrackingOptions::validate() const
{
	const char* s = "vo.tracking";
	require(descriptor_high > 0 && descriptor_high <= 256, s, "descriptor_high", "must be in (0, 256]");
	require(descriptor_low > 0 && descriptor_low <= descriptor_high, s, "descriptor_low", "must be in (0, descriptor_high]");
	require(motion_radius > 0, s, "motion_radius", "must be > 0");
	require(min_motion_matches >= 0, s, "min_motion_matches", "must be >= 0");
	require(reference_radius > 0, s, "reference_radius", "must be > 0");
	require(reference_ratio > 0 && reference_ratio <= 1, s, "reference_ratio", "must be in (0, 1]");
	require(min_reference_matches >= 4, s, "min_reference_matches", "must be >= 4");
	require(min_pose_inliers >= 4, s, "min_pose_inliers", "must be >= 4");
	require(local_radius > 0, s, "local_radius", "must be > 0");
	require(local_ratio > 0 && local_ratio <= 1, s, "local_ratio", "must be in (0, 1]");
	require(max_local_keyframes >= 1, s, "max_local_keyframes", "must be >= 1");
	require(min_local_inliers >= 4, s, "min_local_inliers", "must be >= 4");
	require(pose_rounds >= 1, s, "pose_rounds", "must be >= 1");
	require(pose_iterations >= 1, s, "pose_iterations", "must be >= 1");
	require(chi2 > 0, s, "chi2", "must be > 0");
	require(min_frames_between_keyframes >= 0, s, "min_frames_between_keyframes", "must be >= 0");
	require(keyframe_ref_ratio > 0 && keyframe_ref_ratio <= 1, s, "keyframe_ref_ratio", "must be in (0, 1]");
	require(keyframe_min_inliers >= 0, s, "keyframe_min_inliers", "must be >= 0");
}

void MappingOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	VLO_VO_LOAD(triangulation_neighbours, int);
	VLO_VO_LOAD(min_baseline_ratio, double);
	VLO_VO_LOAD(min_depth_ratio, double);
	VLO_VO_LOAD(max_parallax_cos, double);
	VLO_VO_LOAD(epipolar_chi2, double);
	VLO_VO_LOAD(scale_consistency, double);
	VLO_VO_LOAD(fuse_neighbours, int);
	VLO_VO_LOAD(fuse_radius, double);
	VLO_VO_LOAD(min_found_ratio, double);
	VLO_VO_LOAD(culling_min_observations, int);
	VLO_VO_LOAD(local_ba, bool);
	VLO_VO_LOAD(ba_iterations, int);
	VLO_VO_LOAD(ba_refine_iterations, int);
	VLO_VO_LOAD(max_ba_keyframes, int);
	VLO_VO_LOAD(min_covisibility, int);
	VLO_VO_LOAD(redundant_ratio, double);
	VLO_VO_LOAD(redundant_observers, int);
}

void MappingOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(triangulation_neighbours, "covisible keyframes searched for new points");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_baseline_ratio, "baseline/median depth below: pair skipped");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_depth_ratio, "epipolar search from this fraction of the median depth");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_parallax_cos, "rays closer to parallel are not triangulated");
	MRPT_SAVE_CONFIG_VAR_COMMENT(epipolar_chi2, "squared epipolar distance per sigma^2");
	MRPT_SAVE_CONFIG_VAR_COMMENT(scale_consistency, "distance ratio vs scale ratio tolerance");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fuse_neighbours, "keyframes searched for duplicate points");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fuse_radius, "fusion window per level scale [px]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_found_ratio, "found/visible below: point culled");
	MRPT_SAVE_CONFIG_VAR_COMMENT(culling_min_observations, "at most this many observations later: culled");
	MRPT_SAVE_CONFIG_VAR_COMMENT(local_ba, "local bundle adjustment after each keyframe");
	MRPT_SAVE_CONFIG_VAR_COMMENT(ba_iterations, "first local BA pass (Huber)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(ba_refine_iterations, "second pass without outliers");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_ba_keyframes, "optimised keyframes in the local window");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_covisibility, "shared points for a covisibility edge");
	MRPT_SAVE_CONFIG_VAR_COMMENT(redundant_ratio, "keyframe culled when this fraction of its points ...");
	MRPT_SAVE_CONFIG_VAR_COMMENT(redundant_observers, "... is seen by this many other keyframes");
}

void MappingOptions::validate() const
{
	const char* s = "vo.mapping";
	require(triangulation_neighbours >= 1, s, "triangulation_neighbours", "must be >= 1");
	require(min_baseline_ratio >= 0, s, "min_baseline_ratio", "must be >= 0");
	require(min_depth_ratio > 0 && min_depth_ratio < 1, s, "min_depth_ratio", "must be in (0, 1)");
	require(max_parallax_cos > 0 && max_parallax_cos < 1, s, "max_parallax_cos", "must be in (0, 1)");
	require(epipolar_chi2 > 0, s, "epipolar_chi2", "must be > 0");
	require(scale_consistency >= 1, s, "scale_consistency", "must be >= 1");
	require(fuse_neighbours >= 0, s, "fuse_neighbours", "must be >= 0");
	require(fuse_radius > 0, s, "fuse_radius", "must be > 0");
	require(min_found_ratio >= 0 && min_found_ratio < 1, s, "min_found_ratio", "must be in [0, 1)");
	require(culling_min_observations >= 1, s, "culling_min_observations", "must be >= 1");
	require(ba_iterations >= 0, s, "ba_iterations", "must be >= 0");
	require(ba_refine_iterations >= 0, s, "ba_refine_iterations", "must be >= 0");
	require(max_ba_keyframes >= 2, s, "max_ba_keyframes", "must be >= 2");
	require(min_covisibility >= 1, s, "min_covisibility", "must be >= 1");
	require(redundant_ratio > 0 && redundant_ratio <= 1, s, "redundant_ratio", "must be in (0, 1]");
	require(redundant_observers >= 1, s, "redundant_observers", "must be >= 1");
}

void VoOptions::load(const mrpt::config::CConfigFileBase& c)
{
	orb.loadFromConfigFile(c, "vo.orb");
	init.loadFromConfigFile(c, "vo.init");
	tracking.loadFromConfigFile(c, "vo.tracking");
	mapping.loadFromConfigFile(c, "vo.mapping");
}

void VoOptions::save(mrpt::config::CConfigFileBase& c) const
{
	orb.saveToConfigFile(c, "vo.orb");
	init.saveToConfigFile(c, "vo.init");
	tracking.saveToConfigFile(c, "vo.tracking");
	mapping.saveToConfigFile(c, "vo.mapping");
}

void VoOptions::validate() const
{
	orb.validate();
	init.validate();
	tracking.validate();
	mapping.validate();
}
}  // namespace vlo::vo
