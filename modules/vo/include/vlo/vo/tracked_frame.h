#pragma once
// The frame being tracked: its features, pose estimate and the map point matched to each keypoint.
#include <vlo/vo/features.h>
#include <vlo/vo/geometry.h>

#include <memory>
#include <vector>

namespace vlo::vo
{
class KeyFrame;
class MapPoint;

struct TrackedFrame
{
	long index = -1;
	double t = 0;
	std::shared_ptr<const Features> feat;
	SE3 Tcw = SE3::Identity();
	bool has_pose = false;
	std::vector<MapPoint*> points;  ///< per keypoint
	std::vector<char> outlier;  ///< per keypoint, set by the pose optimisation
	KeyFrame* ref_kf = nullptr;

	TrackedFrame() = default;
	TrackedFrame(long index_, double t_, std::shared_ptr<const Features> f)
		: index(index_), t(t_), feat(std::move(f)), points(feat->size(), nullptr), outlier(feat->size(), 0)
	{
	}
	std::size_t size() const { return points.size(); }
	void clearMatches()
	{
		std::fill(points.begin(), points.end(), nullptr);
		std::fill(outlier.begin(), outlier.end(), 0);
	}
	/// Matched keypoints that are not outliers.
	int inliers() const;
	/// Replaces fused points by their survivors and drops bad ones (before garbage collection).
	void resolvePoints();
};
}  // namespace vlo::vo
