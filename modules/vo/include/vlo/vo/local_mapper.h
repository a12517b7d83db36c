#pragma once
// Local mapping after each new keyframe (ORB-SLAM's LocalMapping): attach the keyframe's points,
// cull young points that are rarely found, triangulate new points with the covisible keyframes, fuse
// duplicates (all inline, in process()); then bundle-adjust the local window and cull redundant
// keyframes and drop those far behind the window, which finish() does at a later, fixed frame
// (bundle_job.h: off the tracking path, so a keyframe's frame does not carry the whole solve).
#include <vlo/core/stage_times.h>
#include <vlo/vo/bundle_job.h>
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

	/// kf->points holds the points tracked in its frame; observations are added here. Starts the
	/// bundle adjustment due when frame `due_frame` starts (on a thread when `threaded`), which
	/// finish() applies; without local BA the keyframes are culled at once and nothing is pending.
	MappingStats process(KeyFrame* kf, long due_frame, bool threaded);
	/// A bundle adjustment waits for finish(); no keyframe may be added meanwhile.
	bool pending() const { return job_ != nullptr; }
	long dueFrame() const { return job_ ? job_->dueFrame() : -1; }
	/// Without a mapping thread, at the frame after the keyframe's: the pending BA's robust pass.
	void advance()
	{
		if (job_) job_->advance();
	}
	/// The map was scaled by s since the pending bundle adjustment was started.
	void scalePending(double s)
	{
		if (job_) job_->scale(s);
	}
	/// Applies the pending bundle adjustment (waiting for it) and culls redundant keyframes around
	/// its keyframe. Stats of the BA and the culling; times under "ba" and "other".
	MappingStats finish();
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
	/// After the BA: culls redundant keyframes around kf and drops those far behind the local window.
	void cullAround(KeyFrame* kf, MappingStats& st);

	Map& map_;
	const PinholeCamera& cam_;
	const ScalePyramid& pyr_;
	const MappingOptions& opt_;
	const TrackingOptions& topt_;
	MatchContext ctx_;
	std::vector<MapPoint*> recent_;
	BundleWindow window_;
	std::unique_ptr<BundleJob> job_;
	KeyFrame* job_kf_ = nullptr;
};
}  // namespace vlo::vo
