#pragma once
// A bundle adjustment as plain data, in three steps: snapshotBundle() copies a window out of the map,
// solveBundle() optimises the copy and reads nothing else (so it may run on another thread while
// the map is tracked against), applyBundle() writes the result back into the map.
#include <vlo/vo/optimizer.h>

#include <array>
#include <vector>

namespace vlo::vo
{
struct BundleProblem
{
	struct Obs
	{
		std::size_t pose, point;  ///< indices into poses and points
		int idx;  ///< keypoint in its keyframe
		Vec2 px;
		double inv_scale, inv_sigma2;  ///< of the keypoint's pyramid level
		bool outlier = false;  ///< set by solveBundle()
	};
	PinholeCamera cam;
	/// Poses Tcw * Ta^-1 (relative to the anchor camera): w.local, then w.fixed.
	std::vector<std::array<double, 6>> poses;
	std::size_t n_local = 0;  ///< poses optimised; the others are held
	/// Held when given, or when none of the fixed poses is in a pass (npos: none).
	std::size_t gauge = npos;
	static constexpr std::size_t npos = static_cast<std::size_t>(-1);
	bool gauge_always = false;  ///< a gauge was asked for: held in every pass
	/// Points in the anchor's camera frame, as w.points.
	std::vector<std::array<double, 3>> points;
	std::vector<Obs> obs;
	BundleStats stats;
};

/// Copies the window: poses relative to its anchor, points in the anchor's camera, the observations
/// among them. When no keyframe is fixed, `gauge` (or the anchor) is held.
BundleProblem snapshotBundle(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr,
	const KeyFrame* gauge = nullptr);
/// `iterations` with a Huber kernel, marks observations with chi2 above the threshold or behind the
/// camera as outliers, then `refine_iterations` without the kernel over the inliers: solveRobust()
/// then solveRefine(), which may run at different times (bundle_job.h) with the same result.
void solveBundle(BundleProblem& p, int iterations, int refine_iterations, double chi2);
/// solveBundle's first pass: `iterations` with a Huber kernel over every observation.
void solveRobust(BundleProblem& p, int iterations, double chi2);
/// solveBundle's second pass: `refine_iterations` without the kernel over the inliers of the
/// current solution, then the outliers marked.
void solveRefine(BundleProblem& p, int refine_iterations, double chi2);
/// Writes the solution into w's keyframes and points (w as given to snapshotBundle) and erases the
/// outlier observations from the map. `scale`: the map was scaled by it, about any point, since the
/// snapshot (relative poses and anchor-frame points scale with it; the anchor's pose is read now).
BundleStats applyBundle(const BundleWindow& w, const BundleProblem& p, double scale = 1.0);
}  // namespace vlo::vo
