#pragma once
// State of VisualOdometry, shared by its implementation files.
#include <vlo/vo/local_mapper.h>
#include <vlo/vo/map_initializer.h>
#include <vlo/vo/orb_extractor.h>
#include <vlo/vo/tracker.h>
#include <vlo/vo/visual_odometry.h>

#include <functional>

namespace vlo::vo
{
struct VisualOdometry::Impl
{
	Impl(const PinholeCamera& c, const VoOptions& o);

	VoFrameInfo process(const cv::Mat& gray, double t);
	bool track(TrackedFrame& cur, VoFrameInfo& info);
	void insertKeyFrame(TrackedFrame& cur, VoFrameInfo& info);
	/// Applies the pending local BA of the last keyframe when it is due, else runs its robust pass
	/// (one thread, once). Applied, the last frame keeps its pose: the next motion then carries the
	/// keyframe's correction, as the keyframe's own motion does when the BA runs inline, so the
	/// motions add up to the adjusted map (moving the last frame with its keyframe, as ORB-SLAM's
	/// tracking does, dropped that correction: VO ATE 0.79 instead of 0.39 m on the 400-frame urban
	/// drive).
	void continueMapping(VoFrameInfo& info);
	void initialise(TrackedFrame& cur, VoFrameInfo& info);
	void startMap(InitResult& r, TrackedFrame& cur, VoFrameInfo& info);
	void lose();
	/// Rescales pose T (Tcw) about the anchor pose Ta: translation relative to it times s.
	static void scaleAbout(SE3& T, const SE3& Ta, double s);
	/// Applies f to the last frame's pose and s to the motion model, keeping the output continuous.
	void rescaleCurrent(const std::function<void(SE3&)>& f, double s);

	PinholeCamera cam;
	VoOptions opt;
	OrbExtractor extractor;
	Tracker tracker;
	MapInitializer init;
	std::unique_ptr<Map> map;
	std::unique_ptr<LocalMapper> mapper;

	VoState state = VoState::NotInitialized;
	TrackedFrame last;  ///< the last frame, tracked in the current map when last.has_pose
	std::shared_ptr<const Features> current_feat;
	SE3 velocity = SE3::Identity();  ///< Tcw(k) * Tcw(k-1)^-1
	bool has_velocity = false;
	int weak_frames = 0;  ///< frames in a row kept with fewer than min_local_inliers
	KeyFrame* last_kf = nullptr;
	long last_kf_frame = -1;
	/// The current map's world frame in the trajectory frame (re-anchored when the map is rescaled).
	SE3 traj_T_map = SE3::Identity();
	int map_id = -1, reinits = 0;
	bool metric = false;  ///< the current map's scale was set by setMapScale()
	bool mapping_thread = false;  ///< local BA on a thread of its own (same results)
	long frames = 0;

	/// Where the trajectory stood when tracking was lost, to place the next map.
	struct LostTrack
	{
		SE3 pose = SE3::Identity();  ///< camera in the trajectory frame
		SE3 velocity = SE3::Identity();
		long index = -1;
		double median_depth = 1;
	};
	std::optional<LostTrack> lost;
	VoFrameInfo info;
};
}  // namespace vlo::vo
