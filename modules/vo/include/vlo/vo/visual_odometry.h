#pragma once
// Monocular visual odometry after ORB-SLAM2 (tracking and local mapping, no loop closing):
// process() extracts features, initialises a map or tracks the frame, and runs local mapping when it
// makes a keyframe, its bundle adjustment entering the map [vo.mapping] mapping_delay frames later
// (on a thread of its own with useMappingThread(); the results are the same). After LOST a new map is initialised and placed where the
// old trajectory left off, so the output trajectory continues (see doc/VO.md for its scale).
//
// For the scale corrector: each frame's relative motion (VoFrameInfo), rescaleAboutWindow() (the whole
// map, about the local window's earliest keyframe) for a drift correction, and setMapScale() (about
// the map's origin) for the metric scale of a fresh map.
#include <vlo/core/stage_times.h>
#include <vlo/vo/features.h>
#include <vlo/vo/geometry.h>
#include <vlo/vo/options.h>

#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace vlo::vo
{
enum class VoState
{
	NotInitialized,  ///< no map yet (or being re-initialised after LOST)
	Ok,
	Lost  ///< tracking failed at this frame; a new map is being initialised
};
const char* toString(VoState s);

struct VoFrameInfo
{
	long index = -1;  ///< frames fed so far, from 0
	double t = 0;
	VoState state = VoState::NotInitialized;
	std::string reason;  ///< how the frame was tracked, or why it was not
	/// Camera pose in the trajectory frame (the camera at the first map's first keyframe), map units.
	std::optional<SE3> pose;
	/// Pose of this camera in the previous frame's camera (map units), when both are tracked in one map.
	std::optional<SE3> motion;
	/// Camera pose in the current map's frame (its first keyframe), map units: what setMapScale() scales.
	std::optional<SE3> map_pose;
	int features = 0, matches = 0, map_points = 0, keyframes = 0;
	int reinits = 0;  ///< maps started after the first one
	int map_id = -1;  ///< counts maps from 0
	bool keyframe = false;  ///< this frame became a keyframe
	bool new_map = false;  ///< a map was initialised at this frame (its scale is arbitrary)
	/// setMapScale() was called on the current map since it was made: map units are metres. Until
	/// then lever arms (metric) cannot be combined with the poses.
	bool metric = false;
	StageTimes ms{{"extract", "track", "mapping"}};
	/// Local mapping detail when a keyframe was made: its stages and the bundle adjustment's size.
	StageTimes mapping_ms{{"triangulate", "fuse", "ba", "other"}};
	int new_points = 0, ba_keyframes = 0, ba_fixed = 0, ba_points = 0;
};

class VisualOdometry
{
   public:
	/// Throws InputError for invalid options or camera.
	VisualOdometry(const PinholeCamera& cam, const VoOptions& opt);
	~VisualOdometry();
	VisualOdometry(const VisualOdometry&) = delete;
	VisualOdometry& operator=(const VisualOdometry&) = delete;

	/// gray: 8-bit, one channel, the camera's size. Never throws for image content (blank, dark).
	VoFrameInfo process(const cv::Mat& gray, double t);
	/// Solves each keyframe's local bundle adjustment on a thread beside tracking (default: off, solved
	/// when due). Changes no result.
	void useMappingThread(bool on);

	// What a scale corrector's decision does to the map, between frames.
	/// Scales the whole map by s about the local window's earliest optimised keyframe (the window:
	/// keyframes of the last local BA, optimised and fixed, and their points), with the current pose
	/// and motion model, so that every observation stays consistent. The
	/// output trajectory stays continuous (later motions are s times longer). False without a map.
	bool rescaleAboutWindow(double s);
	/// Scales the whole current map about its origin (first keyframe), with the current pose and
	/// motion model: for the metric scale right after initialisation (output stays continuous).
	/// False without a map.
	bool setMapScale(double s);

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};
}  // namespace vlo::vo
