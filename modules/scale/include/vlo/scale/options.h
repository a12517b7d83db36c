#pragma once
// Options of the scale corrector (paper sections III-B/C), INI section [scale]. Every default below is
// the value used when the key is absent; saveToConfigFile() writes them all with a comment.
#include <vlo/core/option_table.h>

namespace vlo::scale
{
/// Corner test applied at a projected LiDAR pixel before the gradient test.
enum class KeypointTest
{
	Fast9,  ///< 9 contiguous pixels of the radius-3 circle brighter or darker by fast_threshold
	Fast12Pretest,  ///< the relaxed test for sparse LiDAR: the 4 compass pixels of that circle
	None  ///< gradient test alone (ablation)
};
const char* toString(KeypointTest t);

struct ScaleOptions : public OptionSet
{
	// Projection of scan L(i-1) into image C(i-1).
	double min_depth = 1.0;  ///< [m] along the optical axis; nearer points are ignored
	double max_depth = 80.0;  ///< [m]; farther points have too little parallax (0 = no limit)
	int border = 8;  ///< [px] margin kept free at the image edges (>= 4: the FAST circle fits)

	// Keypoint selection among projected pixels.
	KeypointTest keypoint_test = KeypointTest::Fast9;
	int fast_threshold = 10;  ///< [grey levels] intensity difference of the corner tests
	int fast12_min_count = 3;  ///< compass pixels that must pass the pre-test (3: original FAST, 4: strict)
	bool fast12_same_sign = false;  ///< true: all brighter or all darker (FAST-12 proper); false: |difference| > t
	double gradient_threshold = 5.0;  ///< [grey levels / px] Sobel magnitude / 8 at the keypoint
	double preselect_min_abs_cos = 0.4;  ///< eq. 4 in C(i-1) before NMS and tracking (0 = off; not in the paper)
	int nms_cell = 12;  ///< [px] grid cell of the non-maximum suppression: one keypoint per cell
	int max_keypoints = 200;  ///< cap after NMS, highest gradient first: bounds the LK time

	// Pyramidal Lucas-Kanade from C(i-1) to C(i).
	int lk_window = 11;  ///< [px] side of the tracking window (small: less perspective warp, faster)
	int lk_levels = 4;  ///< pyramid levels above the full image (4: flows up to ~100 px)
	int lk_iterations = 20;
	double lk_epsilon = 0.03;  ///< [px] convergence step
	bool lk_rotation_prior = true;  ///< start LK where the VO rotation alone moves the point (not in the paper)
	bool lk_forward_backward = true;  ///< track back into C(i-1) and require a round trip ...
	double lk_fb_max_error = 0.5;  ///< [px] ... closer than this

	// Culling with the VO relative pose (both stages switchable for the ablation).
	bool cull_epipolar = true;
	double epipolar_max_error = 0.5;  ///< [px] normal distance to the epipolar line (eq. 3)
	bool cull_gradient = true;
	double min_abs_cos = 0.5;  ///< |cos| of epipolar direction vs image gradient in C(i) (eq. 4)

	// Triangulation and scale.
	double min_parallax_deg = 0.5;  ///< [deg] between the two viewing rays
	int ransac_iterations = 200;  ///< hypotheses; with fewer samples than this, every sample is tried
	double ransac_tolerance = 0.05;  ///< inlier band |s_j - s| <= tolerance * s
	int ransac_seed = 1;  ///< same input, same estimate
	int min_inliers = 15;  ///< fewer survivors at any stage: no estimate
	double min_inlier_ratio = 0.3;  ///< of the triangulated points

	// ScaleCorrectionPolicy.
	double correction_threshold = 0.02;  ///< apply when |s - 1| >= this (the paper's 2 %)
	/// The first full correction window after the initial estimate corrects when |median - 1| >= this
	/// (the initial estimate is one frame pair's, scattered by 2-4 %); later windows use
	/// correction_threshold. 0 = off: correction_threshold for every window.
	double initial_refine_threshold = 0.0;
	/// While that window fills (from 5 estimates on), correct as soon as its median is off by more than
	/// this many standard errors (and by initial_refine_threshold); the window then starts again on the
	/// corrected map. 0 = wait for the full window.
	double initial_refine_sigmas = 2.0;
	bool correction_enabled = true;  ///< false: only the first estimate (initial metric scale) is applied
	/// Median of the last N valid estimates decides a correction (1 = each estimate alone, the paper).
	/// Single estimates scatter by 2-4 %, as much as the 2 % threshold: rescaling the VO on each of
	/// them (or on a median of 5) disturbs it more than it corrects (doc/SCALE.md).
	int correction_window = 15;

   protected:
	void declare(OptionTable& t) override;
	void checkRelations() const override;
};
}  // namespace vlo::scale
