#pragma once
// Nonlinear least squares: pose-only optimisation of a tracked frame (core's robust pose solver),
// and bundle adjustment (vlo's own Levenberg-Marquardt, src/bundle_solver.h) of a window of
// keyframes and their points, expressed in the frame of the window's earliest keyframe (paper
// III-C) so that the window can be rescaled about it.
#include <vlo/vo/keyframe.h>
#include <vlo/vo/map_point.h>
#include <vlo/vo/tracked_frame.h>

#include <vector>

namespace vlo::vo
{
/// Optimises f.Tcw against its matched points (Huber, then plain least squares from the third
/// round as ORB-SLAM), re-marking outliers after each round. Returns the number of inliers.
int optimizePose(TrackedFrame& f, const PinholeCamera& cam, const ScalePyramid& pyr, int rounds, int iterations,
	double chi2);

struct BundleWindow
{
	std::vector<KeyFrame*> local;  ///< optimised keyframes
	std::vector<KeyFrame*> fixed;  ///< observe the points but stay put
	std::vector<MapPoint*> points;
	KeyFrame* anchor = nullptr;  ///< earliest local keyframe: the frame the problem is written in
};

struct BundleStats
{
	int keyframes = 0, fixed = 0, points = 0, observations = 0, outliers = 0;
	double initial_cost = 0, final_cost = 0;
};

/// Runs `iterations` with a Huber kernel, drops observations with chi2 above the threshold or
/// behind the camera, then `refine_iterations` without the kernel; erases outlier observations
/// from the map. When no keyframe is fixed, keyframe `gauge` (or the anchor) is held.
BundleStats bundleAdjust(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr, int iterations,
	int refine_iterations, double chi2, const KeyFrame* gauge = nullptr);

/// The local window of ORB-SLAM's local BA around kf: kf and its best covisible keyframes
/// (max_keyframes in all), their points, and the other keyframes observing those points (fixed).
BundleWindow localWindow(KeyFrame* kf, int max_keyframes);
}  // namespace vlo::vo
