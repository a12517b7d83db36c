#pragma once
// Tracking of one frame against the map (ORB-SLAM's Tracking without relocalisation): a first pose
// from the constant-velocity motion model or, failing that, from the reference keyframe; then the
// local map (keyframes sharing points with the frame and their neighbours) refines it. Also the
// keyframe decision.
#include <vlo/vo/matcher.h>

#include <string>
#include <vector>

namespace vlo::vo
{
class Tracker
{
   public:
	Tracker(const PinholeCamera& cam, const ScalePyramid& pyr, const TrackingOptions& opt);

	/// cur.Tcw = velocity * last.Tcw, then projection search and pose optimisation.
	bool withMotionModel(TrackedFrame& cur, const TrackedFrame& last, const SE3& velocity, std::string& why);
	/// Descriptor search of ref's points around their projection with `start` (the pose guess).
	bool withReferenceKeyFrame(TrackedFrame& cur, KeyFrame* ref, const SE3& start, std::string& why);
	/// Adds the local map's points and re-optimises; sets cur.ref_kf. Returns the inliers.
	int withLocalMap(TrackedFrame& cur);
	/// ORB-SLAM's decision with local mapping always idle (single thread).
	bool needKeyFrame(int inliers, const KeyFrame* ref, long frames_since_keyframe, std::size_t n_keyframes) const;

   private:
	/// Optimises, drops outlier matches, returns the inliers that are map points.
	int optimizeAndClean(TrackedFrame& cur);
	void updateLocalMap(TrackedFrame& cur);

	const PinholeCamera& cam_;
	const ScalePyramid& pyr_;
	const TrackingOptions& opt_;
	MatchContext ctx_;
	std::vector<KeyFrame*> local_kfs_;
	std::vector<MapPoint*> local_points_;
};
}  // namespace vlo::vo
