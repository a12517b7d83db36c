// Map (re-)initialisation inside VisualOdometry, and the placement of a new map in the trajectory.
#include <vlo/core/se3.h>
#include <vlo/core/stopwatch.h>

#include "vo_impl.h"

namespace vlo::vo
{
void VisualOdometry::Impl::initialise(TrackedFrame& cur, VoFrameInfo& inf)
{
	const auto t0 = SteadyClock::now();
	InitResult r = init.feed(cur);
	inf.matches = r.matches;
	inf.reason = r.reason;
	if (r.ok) startMap(r, cur, inf);
	if (r.ok) inf.ms.add("mapping", msSince(t0));
}

void VisualOdometry::Impl::startMap(InitResult& r, TrackedFrame& cur, VoFrameInfo& inf)
{
	map = std::move(r.map);
	mapper = std::make_unique<LocalMapper>(*map, cam, extractor.pyramid(), opt.mapping, opt.tracking);
	BundleWindow w;
	w.local = {r.first, r.second};
	w.anchor = r.first;
	mapper->setWindow(w);

	traj_T_map = SE3::Identity();
	if (lost)
	{
		// Continue the trajectory: the new map's origin (its first keyframe) is put where the last
		// tracked pose, carried on at constant velocity over the frames lost, would be ...
		SE3 P = lost->pose;
		if (opt.tracking.reinit_extrapolate)
			for (long k = lost->index; k < r.first->frame_index; ++k) P = P * lost->velocity.inverse();
		traj_T_map = P;
		// ... and given the old map's median scene depth, i.e. roughly the old scale.
		if (opt.tracking.reinit_keep_depth) map->scale(lost->median_depth);
		++reinits;
		lost.reset();
	}
	++map_id;
	metric = false;
	state = VoState::Ok;

	cur.Tcw = r.second->Tcw;
	cur.has_pose = true;
	cur.points = r.second->points;
	std::fill(cur.outlier.begin(), cur.outlier.end(), 0);
	cur.ref_kf = r.second;
	last_kf = r.second;
	last_kf_frame = cur.index;
	// Per-frame velocity: the initial motion spread evenly over the frames between the two keyframes.
	const long gap = r.second->frame_index - r.first->frame_index;
	velocity = interpolate(SE3::Identity(), r.second->Tcw * r.first->Tcw.inverse(), 1.0 / static_cast<double>(gap));
	has_velocity = true;
	if (gap == 1) inf.motion = r.first->Tcw * r.second->Tcw.inverse();
	inf.new_map = true;
	inf.keyframe = true;
}
}  // namespace vlo::vo
