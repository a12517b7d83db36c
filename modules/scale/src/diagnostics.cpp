#include <vlo/scale/diagnostics.h>

namespace vlo::scale
{
const char* toString(Stage s)
{
	switch (s)
	{
		case Stage::None: return "none";
		case Stage::Tracking: return "tracking";
		case Stage::Epipolar: return "epipolar";
		case Stage::Gradient: return "gradient";
		case Stage::Triangulation: return "triangulation";
		case Stage::Ransac: return "ransac";
	}
	return "?";
}

const char* toString(Reason r)
{
	switch (r)
	{
		case Reason::Ok: return "ok";
		case Reason::BadPose: return "bad_pose";
		case Reason::DegenerateMotion: return "degenerate_motion";
		case Reason::FewProjected: return "few_projected";
		case Reason::FewKeypoints: return "few_keypoints";
		case Reason::FewTracks: return "few_tracks";
		case Reason::FewCulled: return "few_culled";
		case Reason::FewTriangulated: return "few_triangulated";
		case Reason::FewInliers: return "few_inliers";
	}
	return "?";
}
}  // namespace vlo::scale
