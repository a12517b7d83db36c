#pragma once
// A 3D point of the map: position (world), the keyframes that observe it, a representative
// descriptor, and the range of distances and the mean viewing direction in which it can be matched.
#include <vlo/vo/features.h>
#include <vlo/vo/geometry.h>

#include <array>
#include <cstdint>
#include <vector>

namespace vlo::vo
{
class KeyFrame;

struct Observation
{
	KeyFrame* kf = nullptr;
	int idx = -1;  ///< keypoint index in kf
};

class MapPoint
{
   public:
	MapPoint(long id, const Vec3& pos, KeyFrame* ref);

	long id;
	Vec3 pos;
	std::array<uint8_t, 32> desc{};
	Vec3 normal = Vec3::Zero();  ///< mean viewing direction (unit)
	double min_dist = 0, max_dist = 0;  ///< scale-invariance range
	KeyFrame* ref_kf;
	long first_kf_id;  ///< keyframe that created it (culling of recent points)
	int visible = 1, found = 1;  ///< in a tracked frame's frustum / matched there
	bool bad = false;
	MapPoint* replaced = nullptr;  ///< set when fused into another point
	/// Marks used by searches so a point is taken once per pass (frame or keyframe id).
	long mark_local = -1, mark_seen = -1, mark_fuse = -1, mark_ba = -1;

	const std::vector<Observation>& observations() const { return obs_; }
	int numObservations() const { return static_cast<int>(obs_.size()); }
	int indexIn(const KeyFrame* kf) const;  ///< -1 when kf does not observe it
	void addObservation(KeyFrame* kf, int idx);
	/// Drops kf's observation; the point turns bad below 2 observations.
	void eraseObservation(KeyFrame* kf);
	/// Removes the point from every keyframe observing it.
	void setBad();
	/// Moves every observation to `other` (unless that keyframe already sees `other`) and turns bad.
	void replaceWith(MapPoint* other);
	/// The live point this one was fused into (itself when not replaced).
	MapPoint* resolved();

	/// Descriptor with the least median distance to all observed ones (ORB-SLAM).
	void updateDescriptor();
	void updateNormalAndDepth(const ScalePyramid& pyr);
	int predictLevel(double dist, const ScalePyramid& pyr) const { return pyr.predictLevel(max_dist, dist); }
	double foundRatio() const { return static_cast<double>(found) / visible; }

   private:
	std::vector<Observation> obs_;
};
}  // namespace vlo::vo
