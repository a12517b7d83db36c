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

void ScaleOptions::declare(OptionTable& t)
{
	t.add("min_depth", min_depth, "> 0", "[m] LiDAR points nearer than this (camera z) are not projected");
	t.add("max_depth", max_depth, ">= 0", "[m] nor farther than this (0 = no limit)");
	t.add("border", border, ">= 4", "[px] image margin without keypoints (>= 4)");
	std::vector<std::pair<std::string, KeypointTest>> tests;
	for (auto k : {KeypointTest::Fast9, KeypointTest::Fast12Pretest, KeypointTest::None}) tests.emplace_back(toString(k), k);
	t.choice("keypoint_test", keypoint_test, tests,
		"fast9 (dense LiDAR) | fast12_pretest (sparse LiDAR) | none");
	t.add("fast_threshold", fast_threshold, "[1, 254]", "[grey levels] intensity difference of the corner test");
	t.add("fast12_min_count", fast12_min_count, "[3, 4]", "compass pixels (of 4) that must pass the FAST-12 pre-test");
	t.add("fast12_same_sign", fast12_same_sign, "true | false", "pre-test pixels all brighter or all darker (false: either)");
	t.add("gradient_threshold", gradient_threshold, ">= 0", "[grey levels/px] smallest Sobel gradient (magnitude/8)");
	t.add("preselect_min_abs_cos", preselect_min_abs_cos, "[0, 1)", "|cos| pre-test in C(i-1) toward the epipole (0 = off)");
	t.add("nms_cell", nms_cell, ">= 1", "[px] grid cell of the non-maximum suppression");
	t.add("max_keypoints", max_keypoints, ">= 1", "keypoints kept after suppression, strongest gradient first");
	t.add("lk_window", lk_window, ">= 5", "[px] Lucas-Kanade window side (odd)");
	t.add("lk_levels", lk_levels, "[0, 6]", "Lucas-Kanade pyramid levels above the image");
	t.add("lk_iterations", lk_iterations, ">= 1", "Lucas-Kanade iterations per level");
	t.add("lk_epsilon", lk_epsilon, "> 0", "[px] Lucas-Kanade convergence step");
	t.add("lk_rotation_prior", lk_rotation_prior, "true | false", "start LK at the pixel predicted by the VO rotation alone");
	t.add("lk_forward_backward", lk_forward_backward, "true | false", "track back into C(i-1) and check the round trip");
	t.add("lk_fb_max_error", lk_fb_max_error, "> 0", "[px] largest forward-backward round-trip error");
	t.add("cull_epipolar", cull_epipolar, "true | false", "cull by distance to the epipolar line (eq. 3)");
	t.add("epipolar_max_error", epipolar_max_error, "> 0", "[px] largest normal error to the epipolar line");
	t.add("cull_gradient", cull_gradient, "true | false", "cull by epipolar direction vs image gradient (eq. 4)");
	t.add("min_abs_cos", min_abs_cos, "[0, 1)", "smallest |cos| between epipolar line and gradient");
	t.add("min_parallax_deg", min_parallax_deg, "[0, 90)", "[deg] smallest angle between the two viewing rays");
	t.add("ransac_iterations", ransac_iterations, ">= 1", "RANSAC hypotheses (all samples when fewer)");
	t.add("ransac_tolerance", ransac_tolerance, "(0, 1)", "RANSAC inlier band, relative to the hypothesis");
	t.add("ransac_seed", ransac_seed, "any", "seed of the RANSAC sampling");
	t.add("min_inliers", min_inliers, ">= 1", "fewer survivors at any stage: no estimate");
	t.add("min_inlier_ratio", min_inlier_ratio, "[0, 1]", "smallest inlier fraction of the triangulated points");
	t.add("correction_threshold", correction_threshold, ">= 0", "correct the VO map when |s - 1| >= this");
	t.add("initial_refine_threshold", initial_refine_threshold, ">= 0", "the first full window after the initial estimate corrects when |median - 1| >= this (0: off)");
	t.add("initial_refine_sigmas", initial_refine_sigmas, ">= 0", "that window corrects before it is full when its median is off by this many standard errors (0: waits)");
	t.add("correction_enabled", correction_enabled, "true | false", "false: scale fixed once after initialisation");
	t.add("correction_window", correction_window, ">= 1", "median of the last N valid estimates decides (1 = paper)");
}

void ScaleOptions::checkRelations() const
{
	require(max_depth == 0 || max_depth > min_depth, "max_depth", "must be 0 or > min_depth");
	require(lk_window % 2 == 1, "lk_window", "must be odd");
}
}  // namespace vlo::scale
