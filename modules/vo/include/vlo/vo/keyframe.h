#pragma once
// A keyframe: a frame's features and pose kept in the map, the map points it observes (per
// keypoint), and its covisibility edges (keyframes sharing points, weighted by their number).
#include <vlo/vo/features.h>
#include <vlo/vo/geometry.h>

#include <memory>
#include <utility>
#include <vector>

namespace vlo::vo
{
class MapPoint;

class KeyFrame
{
   public:
	KeyFrame(long id, long frame_index, double t, std::shared_ptr<const Features> features, const SE3& Tcw);

	long id, frame_index;
	double t;
	SE3 Tcw;
	std::shared_ptr<const Features> feat;
	std::vector<MapPoint*> points;  ///< per keypoint, nullptr where none
	bool bad = false;

	Vec3 centre() const { return vo::centre(Tcw); }
	const cv::KeyPoint& key(int i) const { return feat->keys[static_cast<std::size_t>(i)]; }
	/// Points observed by at least min_obs keyframes.
	int trackedPoints(int min_obs) const;
	/// Median depth of its map points in this camera (0 without points).
	double medianDepth() const;
	/// Removes it from its points and from the covisibility graph.
	void setBad();

	// Covisibility graph (covisibility.cpp).
	/// Recomputes this keyframe's edges from its points (weight >= min_weight, or the best one).
	void updateConnections(int min_weight);
	void addConnection(KeyFrame* kf, int weight);
	void eraseConnection(KeyFrame* kf);
	int weight(const KeyFrame* kf) const;
	/// Neighbours by decreasing weight (ties by id); n < 0: all.
	std::vector<KeyFrame*> bestCovisibles(int n) const;
	const std::vector<std::pair<KeyFrame*, int>>& connections() const { return connections_; }

	/// Marks used by searches so a keyframe or point is taken once per pass (frame or keyframe id).
	long mark_local = -1, mark_fuse = -1, mark_ba = -1, mark_fixed = -1;

   private:
	void sortConnections();
	std::vector<std::pair<KeyFrame*, int>> connections_;
};
}  // namespace vlo::vo
