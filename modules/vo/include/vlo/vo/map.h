#pragma once
// Owns the keyframes and map points of one map. Objects turned bad stay allocated until
// collectGarbage(), which the composing class calls once per frame after dropping its references.
#include <vlo/vo/keyframe.h>
#include <vlo/vo/map_point.h>

#include <memory>
#include <vector>

namespace vlo::vo
{
class Map
{
   public:
	KeyFrame* addKeyFrame(long frame_index, double t, std::shared_ptr<const Features> f, const SE3& Tcw);
	MapPoint* addPoint(const Vec3& pos, KeyFrame* ref);
	/// A point triangulated from keypoint ia of keyframe a and ib of b: observed by both and linked from
	/// both, its descriptor, normal and depth range computed.
	MapPoint* addPointSeenBy(const Vec3& pos, KeyFrame* ref, KeyFrame* a, int ia, KeyFrame* b, int ib,
		const ScalePyramid& pyr);

	/// Live keyframes in creation order.
	std::vector<KeyFrame*> keyFrames() const;
	std::size_t numKeyFrames() const;
	std::size_t numPoints() const;
	/// Live points, in creation order.
	std::vector<MapPoint*> points() const;
	/// Turns bad the keyframes far behind: all but the newest `keep_newest` live ones, except the map's
	/// first keyframe (the origin) and those in `in_use`. Their points turn bad when fewer than two keyframes
	/// still see them. Without loop closing such keyframes are never matched again (ORB-SLAM's local map
	/// loses them too); keeping them would let the map grow with the drive. keep_newest 0: none dropped.
	/// Returns how many.
	int dropOldKeyFrames(std::size_t keep_newest, const std::vector<KeyFrame*>& in_use);
	/// Frees bad keyframes and points. No one may hold a pointer to them any more.
	void collectGarbage();
	/// Scales the map about the world origin (the first keyframe's camera for a fresh map).
	void scale(double s);

   private:
	std::vector<std::unique_ptr<KeyFrame>> kfs_;
	std::vector<std::unique_ptr<MapPoint>> points_;
	long next_kf_ = 0, next_point_ = 0;
};
}  // namespace vlo::vo
