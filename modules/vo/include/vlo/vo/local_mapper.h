#pragma once
// Local mapping after each new keyframe (ORB-SLAM's LocalMapping, run inline): attach the
// keyframe's points, cull young points that are rarely found, triangulate new points with the
// covisible keyframes, fuse duplicates, bundle-adjust the local window, cull redundant keyframes and
// drop those far behind the window.
#include <vlo/core/stage_times.h>
#include <vlo/vo/map.h>
#include <vlo/vo/matcher.h>
#include <vlo/vo/optimizer.h>

namespace vlo::vo
{
struct MappingStats
{
	int new_points = 0, fused = 0, culled_points = 0, culled_keyframes = 0, dropped_keyframes = 0;
	BundleStats ba;
	StageTimes ms{{"triangulate", "fuse", "ba", "other"}};
};

class LocalMapper
{
   public:
	LocalMapper(Map& map, const PinholeCamera& cam, const ScalePyramid& pyr, const MappingOptions& opt,
		const TrackingOptions& topt);

	/// kf->points holds the points tracked in its frame; observations are added here.
	MappingStats process(KeyFrame* kf);
	const MappingStats& lastStats() const { return stats_; }
	/// Registers points made elsewhere (map initialisation) for the young-point culling.
	void addRecent(MapPoint* mp) { recent_.push_back(mp); }
	/// The window of the last local bundle adjustment (bad keyframes dropped on scrub()).
	const BundleWindow& window() const { return window_; }
	void setWindow(BundleWindow w) { window_ = std::move(w); }
	/// Drops references to bad objects (before the map's garbage collection).
	void scrub();

   private:
	void attach(KeyFrame* kf);
	int cullRecentPoints(const KeyFrame* kf);
	int createPoints(KeyFrame* kf);
	int fuseNeighbours(KeyFrame* kf);
	int cullKeyFrames(KeyFrame* kf);

	Map& map_;
	const PinholeCamera& cam_;
	const ScalePyramid& pyr_;
	const MappingOptions& opt_;
	const TrackingOptions& topt_;
	MatchContext ctx_;
	std::vector<MapPoint*> recent_;
	BundleWindow window_;
	MappingStats stats_;
};
}  // namespace vlo::vo
