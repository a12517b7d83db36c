#pragma once
// Descriptor matching guided by geometry (ORB-SLAM's ORBmatcher without bags of words): projection
// of map points into a frame, windowed search for initialisation and the reference-keyframe
// fall-back, epipolar search between keyframes for triangulation, and fusion of duplicates.
#include <vlo/vo/keyframe.h>
#include <vlo/vo/map_point.h>
#include <vlo/vo/options.h>
#include <vlo/vo/tracked_frame.h>

#include <utility>
#include <vector>

namespace vlo::vo
{
struct MatchContext
{
	const PinholeCamera& cam;
	const ScalePyramid& pyr;
	const TrackingOptions& opt;  ///< descriptor thresholds, orientation check, windows, ratios
};

/// Keeps the matches whose keypoint rotation falls in the three dominant 30-degree bins.
class RotationHistogram
{
   public:
	void add(float angle1, float angle2, int match);
	/// Matches outside the dominant bins (ORB-SLAM keeps the 2nd and 3rd only above 10% of the 1st).
	std::vector<int> rejected() const;

   private:
	static constexpr int kBins = 12;
	std::vector<int> bins_[kBins];
};

/// Motion model: projects the last frame's inlier points with cur.Tcw, window radius * level scale.
int searchByProjection(TrackedFrame& cur, const TrackedFrame& last, double radius, const MatchContext& ctx);

/// Local map: points not yet matched in cur and inside its frustum (visibility counted), window by
/// viewing angle and predicted level, best/second-best ratio on the same level.
int searchLocalPoints(TrackedFrame& cur, const std::vector<MapPoint*>& local, const MatchContext& ctx);

/// Reference-keyframe fall-back: each of kf's points is looked for around its position predicted by
/// `predicted` (pose of cur), or around its keypoint in kf when null; window reference_radius.
int searchKeyFrame(const KeyFrame& kf, TrackedFrame& cur, const SE3* predicted, const MatchContext& ctx);

/// Initialisation: keypoints of f1 up to max_level matched in f2 on their own level around prev (the
/// last match position of each, updated). Returns for each keypoint of f1 the index in f2 or -1.
std::vector<int> searchForInitialization(const Features& f1, const Features& f2, std::vector<Vec2>& prev,
	double radius, double ratio, int max_level, const MatchContext& ctx);

/// Unmatched keypoints of k1 and k2 on corresponding epipolar segments (depth >= min_depth in k1).
std::vector<std::pair<int, int>> searchForTriangulation(
	const KeyFrame& k1, const KeyFrame& k2, double min_depth, double epipolar_chi2, const MatchContext& ctx);

/// Projects points into kf: a point lands on a free keypoint (new observation) or on one with a
/// point already, in which case the one with fewer observations is replaced. Returns fusions.
int fuse(KeyFrame* kf, const std::vector<MapPoint*>& points, double radius, const MatchContext& ctx);
}  // namespace vlo::vo
