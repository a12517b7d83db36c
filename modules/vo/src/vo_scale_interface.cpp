// What a scale corrector's decision does to the visual odometry's map.
#include "vo_impl.h"

namespace vlo::vo
{
void VisualOdometry::Impl::rescaleCurrent(const std::function<void(SE3&)>& f, double s)
{
	// The output trajectory stays continuous: the pose just output is kept, later motions scale.
	if (last.has_pose)
	{
		const SE3 pose = traj_T_map * last.Tcw.inverse();
		f(last.Tcw);
		traj_T_map = pose * last.Tcw;
	}
	velocity.translation() *= s;
}

void VisualOdometry::Impl::scaleAbout(SE3& T, const SE3& Ta, double s)
{
	SE3 Tr = T * Ta.inverse();  // pose relative to the anchor camera
	Tr.translation() *= s;
	T = Tr * Ta;
}

bool VisualOdometry::rescaleAboutWindow(double s)
{
	auto& m = *impl_;
	if (!m.map || !m.mapper || !(s > 0) || !m.mapper->window().anchor) return false;
	// The similarity about the window's earliest keyframe is applied to the whole map, not to the window
	// alone: the current frame also tracks points of older keyframes, and those left at the old scale
	// made tracking jump (1.14 km urban drive: the VO's steps tripled after ~25 window-only
	// corrections). A similarity keeps every observation consistent; the map before the window is
	// history (no loop closing) and the output trajectory stays as it was.
	const SE3 Ta = m.mapper->window().anchor->Tcw, Ta_inv = Ta.inverse();
	for (MapPoint* p : m.map->points())
	{
		p->pos = Ta_inv * (s * (Ta * p->pos));
		p->min_dist *= s;
		p->max_dist *= s;
	}
	for (KeyFrame* kf : m.map->keyFrames()) Impl::scaleAbout(kf->Tcw, Ta, s);
	m.mapper->scalePending(s);
	m.rescaleCurrent([&](SE3& T) { Impl::scaleAbout(T, Ta, s); }, s);
	return true;
}

bool VisualOdometry::setMapScale(double s)
{
	auto& m = *impl_;
	if (!m.map || !(s > 0)) return false;
	m.map->scale(s);
	if (m.mapper) m.mapper->scalePending(s);
	m.rescaleCurrent([&](SE3& T) { T.translation() *= s; }, s);
	m.metric = true;
	return true;
}
}  // namespace vlo::vo
