#pragma once
// Options of the monocular visual odometry, one CLoadableOptions struct per stage.
// INI sections: [vo.orb], [vo.init], [vo.tracking], [vo.mapping]. Every default below is the value
// used when the key is absent (most are ORB-SLAM2's); saveToConfigFile() writes them all, commented.
#include <vlo/core/option_table.h>

#include <string>
#include <utility>
#include <vector>

namespace vlo::vo
{
/// ORB features over a scale pyramid.
struct OrbOptions : public OptionSet
{
	/// FAST corners spread by adaptive non-maximal suppression or by ORB-SLAM's quadtree, with
	/// OpenCV's rBRIEF; or opencv: cv::ORB as it is (the strongest corners, clustered on texture).
	std::string detector = "anms";  ///< anms | quadtree | opencv
	/// Per image, spread over the levels as a geometric series. ORB-SLAM2 takes 2000 on KITTI; 1500 keeps
	/// the whole system within 10 Hz on one core at about the same VO accuracy (trees HDL-64: the VO
	/// 32 instead of 44 ms a frame, SE(3) ATE 0.21 against 0.18 m).
	int n_features = 1500;
	double scale_factor = 1.2;  ///< between pyramid levels
	int n_levels = 8;
	int fast_threshold = 20;  ///< FAST threshold; cells with no such corner fall back to ...
	int fast_min_threshold = 7;  ///< ... this lower one
	int edge_threshold = 19;  ///< no feature closer to the image border [px]
	int fallback_cell = 30;  ///< cells [px] in which the lower FAST threshold may be used
	double anms_pool = 10.0;  ///< anms: the strongest pool * wanted corners of a level compete

   protected:
	void declare(OptionTable& t) override;
	void checkRelations() const override;
};

/// Map initialisation from two frames (homography / fundamental matrix model selection).
struct InitOptions : public OptionSet
{
	int min_features = 100;  ///< fewer: the frame cannot be an initialisation frame
	int min_matches = 100;  ///< fewer matches with the reference: the reference is replaced
	double search_radius = 100;  ///< window around the previous match position [px]
	double match_ratio = 0.9;  ///< best / second best descriptor distance
	/// Pyramid levels matched. ORB-SLAM takes the finest only; with spread (hence weaker) corners
	/// that left too few matches on KITTI (doc/VO.md), so the three finest are used.
	int max_level = 2;
	int ransac_iterations = 200;
	double sigma = 1.0;  ///< keypoint noise at level 0 [px] for the model scores
	double homography_ratio = 0.45;  ///< R_H = S_H / (S_H + S_F) above this: homography
	double min_parallax_deg = 1.0;  ///< of the triangulated points (50th largest)
	int min_triangulated = 50;
	double min_good_fraction = 0.9;  ///< of the model inliers that must triangulate (ORB-SLAM 0.9)
	double ambiguity_ratio = 0.75;  ///< second best decomposition's good points below ratio * best
	/// A plane seen from two views has two valid motions: take the one turning less by this margin
	/// (video frames turn little; 0 = never, wait for a clear winner as ORB-SLAM does).
	double planar_rotation_margin_deg = 0.5;
	int ba_iterations = 20;  ///< initial two-view bundle adjustment
	int min_tracked_after_ba = 100;  ///< map points left after the initial BA
	int seed = 1;  ///< RANSAC random sets (deterministic runs)

   protected:
	void declare(OptionTable& t) override;
};

/// Frame-to-frame and frame-to-local-map tracking, keyframe decision, re-initialisation.
struct TrackingOptions : public OptionSet
{
	int descriptor_high = 100;  ///< Hamming distance accepted for projection matches
	int descriptor_low = 50;  ///< ... for triangulation, fusion and keyframe matches
	bool check_orientation = true;  ///< keep the 3 dominant bins of the rotation histogram
	double motion_radius = 15;  ///< motion-model projection window at level 0 [px]
	int min_motion_matches = 20;  ///< fewer: the search is repeated with twice the window
	double reference_radius = 150;  ///< window of the reference-keyframe fallback [px]
	double reference_ratio = 0.7;  ///< best / second best distance in that fallback
	int min_reference_matches = 15;
	int min_pose_inliers = 10;  ///< after the pose optimisation of either first step
	double local_radius = 1.0;  ///< factor on the local-map window (2.5 or 4 px per level scale)
	double local_ratio = 0.8;  ///< best / second best distance on the same level
	int max_local_keyframes = 80;
	int min_local_inliers = 30;  ///< fewer after tracking the local map: LOST (unless weak, below)
	/// A frame with fewer than min_local_inliers but at least this many, after frames tracked with
	/// min_local_inliers, is kept and made a keyframe at once (its new points carry tracking on)
	/// instead of being LOST; at most max_weak_frames of them in a row. 0 = off (ORB-SLAM2: LOST).
	int min_weak_inliers = 20;
	int max_weak_frames = 2;
	int pose_rounds = 4;  ///< pose-only optimisation: rounds of outlier marking ...
	int pose_iterations = 10;  ///< ... of at most this many solver iterations each
	double chi2 = 5.991;  ///< outlier threshold on the squared, sigma-normalised reprojection error
	int min_frames_between_keyframes = 0;
	double keyframe_ref_ratio = 0.9;  ///< tracked < ratio * reference keyframe's points: new keyframe
	int keyframe_min_inliers = 15;  ///< no keyframe from a frame tracked this poorly
	/// Fewer inliers: a keyframe whatever the reference keyframe tracks. A keyframe made from a weakly
	/// tracked frame has few points seen thrice, so the ratio alone waits until tracking is lost.
	int keyframe_weak_inliers = 50;
	/// A frame with fewer inliers that needs a keyframe while the last keyframe's local BA is pending
	/// gets it now: the BA is applied at once instead of at its due frame (ORB-SLAM2's tracking
	/// interrupts the local BA when it needs a keyframe). 0 = wait for the due frame (doc/VO.md).
	int keyframe_interrupt_inliers = 0;
	bool reinit_extrapolate = true;  ///< a new map starts where constant velocity puts it
	bool reinit_keep_depth = true;  ///< a new map gets the old map's median scene depth (scale)

   protected:
	void declare(OptionTable& t) override;
	void checkRelations() const override;
};

/// Local mapping: new points, fusion, culling, local bundle adjustment.
struct MappingOptions : public OptionSet
{
	int triangulation_neighbours = 20;  ///< best covisible keyframes searched for new points
	double min_baseline_ratio = 0.01;  ///< baseline / neighbour's median depth below: skipped
	double min_depth_ratio = 0.05;  ///< epipolar search from this fraction of the median depth
	double max_parallax_cos = 0.9998;  ///< rays closer to parallel are not triangulated
	double epipolar_chi2 = 3.84;  ///< squared epipolar distance per sigma^2
	double scale_consistency = 1.5;  ///< distance ratio vs pyramid scale ratio tolerance
	int fuse_neighbours = 20;  ///< covisible keyframes (plus 5 of each) searched for duplicates
	double fuse_radius = 3.0;  ///< projection window per level scale [px]
	double min_found_ratio = 0.25;  ///< found / visible below: the point is culled
	int culling_min_observations = 2;  ///< at most this many observations 2 keyframes later: culled
	bool local_ba = true;
	int ba_iterations = 5;  ///< first local BA pass (Huber) ...
	int ba_refine_iterations = 10;  ///< ... second pass without the outliers
	int max_ba_keyframes = 20;  ///< optimised keyframes (current + best covisible)
	/// Keyframe k's local BA (and keyframe culling) enters the map when frame k + this starts; until
	/// then it runs beside tracking, so no frame waits for it. 0: inline, at keyframe k. With one thread its
	/// robust pass runs at frame k + 1 and its refine pass at k + this (2: one pass per frame).
	int mapping_delay = 2;
	int min_covisibility = 15;  ///< shared points for a covisibility edge
	double redundant_ratio = 0.9;  ///< keyframe culled when this fraction of its points ...
	int redundant_observers = 3;  ///< ... is seen by this many other keyframes at the same scale
	/// The newest this many keyframes stay in the map; older ones that see no point of the local BA window
	/// are dropped with the points only they saw, so that the map does not grow with the drive (0: all kept).
	int keep_keyframes = 40;

   protected:
	void declare(OptionTable& t) override;
};

/// All of the above.
struct VoOptions : public OptionGroup
{
	OrbOptions orb;
	InitOptions init;
	TrackingOptions tracking;
	MappingOptions mapping;

	/// [vo.orb], [vo.init], [vo.tracking], [vo.mapping]
	std::vector<std::pair<std::string, OptionSet*>> parts() override;
};
}  // namespace vlo::vo
