// [vo.orb] and [vo.init].
#include <mrpt/config/CConfigFileBase.h>
#include <vlo/vo/options.h>

#include "option_checks.h"

namespace vlo::vo
{
using detail::require;

void OrbOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	detector = c.read_string_first_word(s, "detector", detector);
	VLO_VO_LOAD(n_features, int);
	VLO_VO_LOAD(scale_factor, double);
	VLO_VO_LOAD(n_levels, int);
	VLO_VO_LOAD(fast_threshold, int);
	VLO_VO_LOAD(fast_min_threshold, int);
	VLO_VO_LOAD(edge_threshold, int);
	VLO_VO_LOAD(fallback_cell, int);
	VLO_VO_LOAD(anms_pool, double);
}

void OrbOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(detector, "anms | quadtree (FAST spread over the image + rBRIEF) | opencv (cv::ORB as is)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(n_features, "features per image over all levels");
	MRPT_SAVE_CONFIG_VAR_COMMENT(scale_factor, "scale between pyramid levels");
	MRPT_SAVE_CONFIG_VAR_COMMENT(n_levels, "pyramid levels");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fast_threshold, "FAST threshold");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fast_min_threshold, "FAST threshold in cells without a strong corner");
	MRPT_SAVE_CONFIG_VAR_COMMENT(edge_threshold, "no feature closer to the border [px]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fallback_cell, "cells [px] where fast_min_threshold may be used");
	MRPT_SAVE_CONFIG_VAR_COMMENT(anms_pool, "anms: strongest pool * wanted corners per level compete");
}

void OrbOptions::validate() const
{
	const char* s = "vo.orb";
	require(detector == "anms" || detector == "quadtree" || detector == "opencv", s, "detector",
		"'" + detector + "' is not anms, quadtree or opencv");
	require(n_features >= 50, s, "n_features", "must be >= 50");
	require(scale_factor > 1.0 && scale_factor < 2.0, s, "scale_factor", "must be in (1, 2)");
	require(n_levels >= 1 && n_levels <= 16, s, "n_levels", "must be in [1, 16]");
	require(fast_threshold > 0 && fast_threshold < 255, s, "fast_threshold", "must be in (0, 255)");
	require(fast_min_threshold > 0 && fast_min_threshold <= fast_threshold, s, "fast_min_threshold",
		"must be in (0, fast_threshold]");
	require(edge_threshold >= 19 && edge_threshold < 100, s, "edge_threshold",
		"must be in [19, 100) (the ORB patch needs 19 px)");
	require(fallback_cell >= 8, s, "fallback_cell", "must be >= 8");
	require(anms_pool >= 1, s, "anms_pool", "must be >= 1");
}

void InitOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	VLO_VO_LOAD(min_features, int);
	VLO_VO_LOAD(min_matches, int);
	VLO_VO_LOAD(search_radius, double);
	VLO_VO_LOAD(match_ratio, double);
	VLO_VO_LOAD(max_level, int);
	VLO_VO_LOAD(ransac_iterations, int);
	VLO_VO_LOAD(sigma, double);
	VLO_VO_LOAD(homography_ratio, double);
	VLO_VO_LOAD(min_parallax_deg, double);
	VLO_VO_LOAD(min_triangulated, int);
	VLO_VO_LOAD(min_good_fraction, double);
	VLO_VO_LOAD(ambiguity_ratio, double);
	VLO_VO_LOAD(planar_rotation_margin_deg, double);
	VLO_VO_LOAD(ba_iterations, int);
	VLO_VO_LOAD(min_tracked_after_ba, int);
	VLO_VO_LOAD(seed, int);
}

void InitOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_features, "fewer: no initialisation from this frame");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_matches, "fewer matches: the reference frame is replaced");
	MRPT_SAVE_CONFIG_VAR_COMMENT(search_radius, "matching window around the previous match [px]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(match_ratio, "best/second best descriptor distance");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_level, "pyramid levels used for initialisation (0: finest only)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(ransac_iterations, "for H and F each");
	MRPT_SAVE_CONFIG_VAR_COMMENT(sigma, "keypoint noise at level 0 for the model scores [px]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(homography_ratio, "R_H = S_H/(S_H+S_F) above: homography");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_parallax_deg, "parallax of the 50th best triangulated point [deg]");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_triangulated, "triangulated points needed");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_good_fraction, "of the model inliers that must triangulate");
	MRPT_SAVE_CONFIG_VAR_COMMENT(ambiguity_ratio, "second best decomposition below ratio * best");
	MRPT_SAVE_CONFIG_VAR_COMMENT(planar_rotation_margin_deg, "planar twofold ambiguity: the motion turning less by this [deg] wins; 0 = wait");
	MRPT_SAVE_CONFIG_VAR_COMMENT(ba_iterations, "initial two-view bundle adjustment iterations");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_tracked_after_ba, "map points needed after the initial BA");
	MRPT_SAVE_CONFIG_VAR_COMMENT(seed, "RANSAC seed");
}

void InitOptions::validate() const
{
	const char* s = "vo.init";
	require(min_features >= 8, s, "min_features", "must be >= 8");
	require(min_matches >= 8, s, "min_matches", "must be >= 8");
	require(search_radius > 0, s, "search_radius", "must be > 0");
	require(match_ratio > 0 && match_ratio <= 1, s, "match_ratio", "must be in (0, 1]");
	require(max_level >= 0, s, "max_level", "must be >= 0");
	require(ransac_iterations >= 1, s, "ransac_iterations", "must be >= 1");
	require(sigma > 0, s, "sigma", "must be > 0");
	require(homography_ratio > 0 && homography_ratio < 1, s, "homography_ratio", "must be in (0, 1)");
	require(min_parallax_deg >= 0, s, "min_parallax_deg", "must be >= 0");
	require(min_triangulated >= 8, s, "min_triangulated", "must be >= 8");
	require(min_good_fraction >= 0 && min_good_fraction <= 1, s, "min_good_fraction", "must be in [0, 1]");
	require(ambiguity_ratio > 0 && ambiguity_ratio <= 1, s, "ambiguity_ratio", "must be in (0, 1]");
	require(planar_rotation_margin_deg >= 0, s, "planar_rotation_margin_deg", "must be >= 0");
	require(ba_iterations >= 0, s, "ba_iterations", "must be >= 0");
	require(min_tracked_after_ba >= 8, s, "min_tracked_after_ba", "must be >= 8");
}
}  // namespace vlo::vo
