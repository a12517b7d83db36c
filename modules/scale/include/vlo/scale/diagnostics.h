#pragma once
// What the scale corrector reports per frame: the estimate, why it is (not) valid, counts and
// milliseconds per stage, and per keypoint the stage that rejected it (for frames.csv and snapshots).
#include <vlo/core/stage_times.h>

#include <opencv2/core/types.hpp>

#include <vector>

namespace vlo::scale
{
/// The stage that rejected a keypoint, in pipeline order; None: survived every stage that ran.
enum class Stage
{
	None,
	Tracking,  ///< LK lost it, forward-backward check failed, or it left the image
	Epipolar,  ///< normal error to the epipolar line too large (eq. 3)
	Gradient,  ///< image gradient too close to perpendicular to the epipolar line (eq. 4)
	Triangulation,  ///< behind a camera or too little parallax
	Ransac  ///< s_j outside the winning inlier band
};
const char* toString(Stage s);

enum class Reason
{
	Ok,
	BadPose,  ///< the VO relative pose is not finite
	DegenerateMotion,  ///< no translation, or too little parallax to triangulate enough points
	FewProjected,  ///< LiDAR points in view
	FewKeypoints,
	FewTracks,
	FewCulled,  ///< after the epipolar culling
	FewTriangulated,
	FewInliers  ///< RANSAC inliers (count or ratio)
};
const char* toString(Reason r);

struct KeypointDiag
{
	int scan_index = -1;  ///< LiDAR point p_j of scan L(i-1)
	cv::Point2f prev;  ///< x_j in C(i-1): the projected LiDAR point
	cv::Point2f cur;  ///< tracked position in C(i) (meaningless when Tracking rejected it)
	float d = 0;  ///< LiDAR depth [m]
	float v = 0;  ///< visual depth [VO units] (0 before triangulation)
	float s = 0;  ///< d / v
	float fb_error = 0, normal_error = 0, abs_cos = 0, parallax_deg = 0;
	Stage rejected_by = Stage::None;
};

struct StageCounts
{
	int projected = 0;  ///< LiDAR points in view
	int corner = 0;  ///< passed the corner test
	int gradient = 0;  ///< ... and the gradient threshold
	int direction = 0;  ///< ... and the gradient direction pre-test (preselect_min_abs_cos)
	int selected = 0;  ///< after NMS and the cap
	int tracked = 0;
	int epipolar_kept = 0;
	int gradient_kept = 0;
	int triangulated = 0;
	int inliers = 0;
};

struct ScaleEstimate
{
	bool valid = false;
	Reason reason = Reason::FewProjected;
	double scale = 0;  ///< mean of the inlier s_j (also set for FewInliers; 0 when not computed)
	double spread = 0;  ///< standard deviation of the inlier s_j
	double inlier_ratio = 0;  ///< inliers / triangulated
	StageCounts counts;
	StageTimes ms{{"project", "select", "track", "cull", "triangulate", "ransac"}};
	std::vector<KeypointDiag> keypoints;  ///< one per selected keypoint
};
}  // namespace vlo::scale
