#include <mrpt/config/CConfigFileBase.h>
#include <vlo/core/error.h>
#include <vlo/scale/options.h>

namespace vlo::scale
{
const char* toString(KeypointTest t)
{
	switch (t)
	{
		case KeypointTest::Fast9: return "fast9";
		case KeypointTest::Fast12Pretest: return "fast12_pretest";
		case KeypointTest::None: return "none";
	}
	return "?";
}

KeypointTest parseKeypointTest(const std::string& name, const std::string& where)
{
	for (auto t : {KeypointTest::Fast9, KeypointTest::Fast12Pretest, KeypointTest::None})
		if (name == toString(t)) return t;
	failInput(where, "'" + name + "' is not one of fast9, fast12_pretest, none");
}

void ScaleOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	MRPT_LOAD_CONFIG_VAR(min_depth, double, c, s);
	MRPT_LOAD_CONFIG_VAR(max_depth, double, c, s);
	MRPT_LOAD_CONFIG_VAR(border, int, c, s);
	keypoint_test = parseKeypointTest(
		c.read_string_first_word(s, "keypoint_test", toString(keypoint_test)), "[" + s + "] keypoint_test");
	MRPT_LOAD_CONFIG_VAR(fast_threshold, int, c, s);
	MRPT_LOAD_CONFIG_VAR(fast12_min_count, int, c, s);
	MRPT_LOAD_CONFIG_VAR(fast12_same_sign, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(gradient_threshold, double, c, s);
	MRPT_LOAD_CONFIG_VAR(preselect_min_abs_cos, double, c, s);
	MRPT_LOAD_CONFIG_VAR(nms_cell, int, c, s);
	MRPT_LOAD_CONFIG_VAR(max_keypoints, int, c, s);
	MRPT_LOAD_CONFIG_VAR(lk_window, int, c, s);
	MRPT_LOAD_CONFIG_VAR(lk_levels, int, c, s);
	MRPT_LOAD_CONFIG_VAR(lk_iterations, int, c, s);
	MRPT_LOAD_CONFIG_VAR(lk_epsilon, double, c, s);
	MRPT_LOAD_CONFIG_VAR(lk_rotation_prior, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(lk_forward_backward, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(lk_fb_max_error, double, c, s);
	MRPT_LOAD_CONFIG_VAR(cull_epipolar, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(epipolar_max_error, double, c, s);
	MRPT_LOAD_CONFIG_VAR(cull_gradient, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(min_abs_cos, double, c, s);
	MRPT_LOAD_CONFIG_VAR(min_parallax_deg, double, c, s);
	MRPT_LOAD_CONFIG_VAR(ransac_iterations, int, c, s);
	MRPT_LOAD_CONFIG_VAR(ransac_tolerance, double, c, s);
	MRPT_LOAD_CONFIG_VAR(ransac_seed, int, c, s);
	MRPT_LOAD_CONFIG_VAR(min_inliers, int, c, s);
	MRPT_LOAD_CONFIG_VAR(min_inlier_ratio, double, c, s);
	MRPT_LOAD_CONFIG_VAR(correction_threshold, double, c, s);
	MRPT_LOAD_CONFIG_VAR(correction_enabled, bool, c, s);
	MRPT_LOAD_CONFIG_VAR(correction_window, int, c, s);
	validate(s);
}

void ScaleOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_depth, "[m] LiDAR points nearer than this (camera z) are not projected");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_depth, "[m] nor farther than this (0 = no limit)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(border, "[px] image margin without keypoints (>= 4)");
	c.write(s, "keypoint_test", std::string(toString(keypoint_test)), mrpt::config::MRPT_SAVE_NAME_PADDING(),
		mrpt::config::MRPT_SAVE_VALUE_PADDING(), "fast9 (dense LiDAR) | fast12_pretest (sparse LiDAR) | none");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fast_threshold, "[grey levels] intensity difference of the corner test");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fast12_min_count, "compass pixels (of 4) that must pass the FAST-12 pre-test");
	MRPT_SAVE_CONFIG_VAR_COMMENT(fast12_same_sign, "pre-test pixels all brighter or all darker (false: either)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(gradient_threshold, "[grey levels/px] smallest Sobel gradient (magnitude/8)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(preselect_min_abs_cos, "|cos| pre-test in C(i-1) toward the epipole (0 = off)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(nms_cell, "[px] grid cell of the non-maximum suppression");
	MRPT_SAVE_CONFIG_VAR_COMMENT(max_keypoints, "keypoints kept after suppression, strongest gradient first");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lk_window, "[px] Lucas-Kanade window side");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lk_levels, "Lucas-Kanade pyramid levels above the image");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lk_iterations, "Lucas-Kanade iterations per level");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lk_epsilon, "[px] Lucas-Kanade convergence step");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lk_rotation_prior, "start LK at the pixel predicted by the VO rotation alone");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lk_forward_backward, "track back into C(i-1) and check the round trip");
	MRPT_SAVE_CONFIG_VAR_COMMENT(lk_fb_max_error, "[px] largest forward-backward round-trip error");
	MRPT_SAVE_CONFIG_VAR_COMMENT(cull_epipolar, "cull by distance to the epipolar line (eq. 3)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(epipolar_max_error, "[px] largest normal error to the epipolar line");
	MRPT_SAVE_CONFIG_VAR_COMMENT(cull_gradient, "cull by epipolar direction vs image gradient (eq. 4)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_abs_cos, "smallest |cos| between epipolar line and gradient");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_parallax_deg, "[deg] smallest angle between the two viewing rays");
	MRPT_SAVE_CONFIG_VAR_COMMENT(ransac_iterations, "RANSAC hypotheses (all samples when fewer)");
	MRPT_SAVE_CONFIG_VAR_COMMENT(ransac_tolerance, "RANSAC inlier band, relative to the hypothesis");
	MRPT_SAVE_CONFIG_VAR_COMMENT(ransac_seed, "seed of the RANSAC sampling");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_inliers, "fewer survivors at any stage: no estimate");
	MRPT_SAVE_CONFIG_VAR_COMMENT(min_inlier_ratio, "smallest inlier fraction of the triangulated points");
	MRPT_SAVE_CONFIG_VAR_COMMENT(correction_threshold, "correct the VO map when |s - 1| >= this");
	MRPT_SAVE_CONFIG_VAR_COMMENT(correction_enabled, "false: scale fixed once after initialisation");
	MRPT_SAVE_CONFIG_VAR_COMMENT(correction_window, "median of the last N valid estimates decides (1 = paper)");
}

void ScaleOptions::validate(const std::string& s) const
{
	auto require = [&](bool ok, const char* key, const std::string& problem) {
		if (!ok) failInput("[" + s + "] " + key, problem);
	};
	require(min_depth > 0, "min_depth", "must be > 0");
	require(max_depth == 0 || max_depth > min_depth, "max_depth", "must be 0 or > min_depth");
	require(border >= 4, "border", "must be >= 4 (the FAST circle has radius 3)");
	require(fast_threshold > 0 && fast_threshold < 255, "fast_threshold", "must be in 1..254");
	require(fast12_min_count == 3 || fast12_min_count == 4, "fast12_min_count", "must be 3 or 4");
	require(gradient_threshold >= 0, "gradient_threshold", "must be >= 0");
	require(preselect_min_abs_cos >= 0 && preselect_min_abs_cos < 1, "preselect_min_abs_cos", "must be in [0, 1)");
	require(nms_cell >= 1, "nms_cell", "must be >= 1");
	require(max_keypoints >= 1, "max_keypoints", "must be >= 1");
	require(lk_window >= 5 && lk_window % 2 == 1, "lk_window", "must be odd and >= 5");
	require(lk_levels >= 0 && lk_levels <= 6, "lk_levels", "must be in 0..6");
	require(lk_iterations >= 1, "lk_iterations", "must be >= 1");
	require(lk_epsilon > 0, "lk_epsilon", "must be > 0");
	require(lk_fb_max_error > 0, "lk_fb_max_error", "must be > 0");
	require(epipolar_max_error > 0, "epipolar_max_error", "must be > 0");
	require(min_abs_cos >= 0 && min_abs_cos < 1, "min_abs_cos", "must be in [0, 1)");
	require(min_parallax_deg >= 0 && min_parallax_deg < 90, "min_parallax_deg", "must be in [0, 90)");
	require(ransac_iterations >= 1, "ransac_iterations", "must be >= 1");
	require(ransac_tolerance > 0 && ransac_tolerance < 1, "ransac_tolerance", "must be in (0, 1)");
	require(min_inliers >= 1, "min_inliers", "must be >= 1");
	require(min_inlier_ratio >= 0 && min_inlier_ratio <= 1, "min_inlier_ratio", "must be in [0, 1]");
	require(correction_threshold >= 0, "correction_threshold", "must be >= 0");
	require(correction_window >= 1, "correction_window", "must be >= 1");
}
}  // namespace vlo::scale
