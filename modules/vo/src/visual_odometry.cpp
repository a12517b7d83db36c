#include <vlo/core/error.h>
#include <vlo/core/se3.h>
#include <vlo/core/stopwatch.h>

#include "vo_impl.h"

namespace vlo::vo
{
namespace
{
/// What LocalMapper::finish() did, into the frame's info.
void addFinished(VoFrameInfo& inf, const MappingStats& st)
{
	inf.mapping_ms.add("ba", st.ms.ms("ba"));
	inf.mapping_ms.add("other", st.ms.ms("other"));
	inf.ba_keyframes = st.ba.keyframes;
	inf.ba_fixed = st.ba.fixed;
	inf.ba_points = st.ba.points;
}
}  // namespace

const char* toString(VoState s)
{
	switch (s)
	{
		case VoState::Ok: return "OK";
		case VoState::Lost: return "LOST";
		default: return "NOT_INITIALIZED";
	}
}

VisualOdometry::Impl::Impl(const PinholeCamera& c, const VoOptions& o)
	: cam(c),
	  opt(o),
	  extractor(opt.orb),
	  tracker(cam, extractor.pyramid(), opt.tracking),
	  init(cam, extractor.pyramid(), opt.init, opt.tracking, opt.mapping)
{
}

VisualOdometry::VisualOdometry(const PinholeCamera& cam, const VoOptions& opt)
{
	if (!cam.valid()) failInput("camera", "invalid intrinsics for the visual odometry");
	opt.validate();
	impl_ = std::make_unique<Impl>(cam, opt);
}

VisualOdometry::~VisualOdometry() = default;

VoFrameInfo VisualOdometry::process(const cv::Mat& gray, double t) { return impl_->process(gray, t); }

void VisualOdometry::useMappingThread(bool on) { impl_->mapping_thread = on; }

VoFrameInfo VisualOdometry::Impl::process(const cv::Mat& gray, double t)
{
	if (gray.type() != CV_8UC1 || gray.cols != cam.width || gray.rows != cam.height)
		failInput("image", "the visual odometry needs 8-bit gray images of the camera's size");
	info = VoFrameInfo();
	info.index = frames++;
	info.t = t;
	auto t0 = SteadyClock::now();
	current_feat = std::make_shared<Features>(extractor.extract(gray));
	info.ms.add("extract", msSince(t0));
	info.features = static_cast<int>(current_feat->size());
	TrackedFrame cur(info.index, t, current_feat);
	if (mapper && mapper->pending()) continueMapping(info);

	t0 = SteadyClock::now();
	const double mapping_before = info.ms.ms("mapping");
	if (state == VoState::Ok)
	{
		if (track(cur, info))
		{
			if (last.has_pose) info.motion = last.Tcw * cur.Tcw.inverse();
		}
		else
		{
			const std::string why = info.reason;
			lose();
			cur.clearMatches();  // they point into the map just dropped
			cur.ref_kf = nullptr;
			cur.has_pose = false;
			initialise(cur, info);  // this frame becomes the new reference
			info.reason = "LOST: " + why + "; " + info.reason;
		}
	}
	else
		initialise(cur, info);
	info.ms.add("track", msSince(t0) - (info.ms.ms("mapping") - mapping_before));

	// Untracked frames stay LOST from a tracking failure until a new map is made.
	info.state = cur.has_pose ? VoState::Ok : state;
	if (cur.has_pose)
	{
		info.pose = traj_T_map * cur.Tcw.inverse();
		info.map_pose = cur.Tcw.inverse();
		cur.resolvePoints();
		if (cur.ref_kf && cur.ref_kf->bad) cur.ref_kf = last_kf;
		last = std::move(cur);
	}
	else
		last = TrackedFrame();
	if (mapper) mapper->scrub();
	if (map) map->collectGarbage();
	info.map_points = map ? static_cast<int>(map->numPoints()) : 0;
	info.keyframes = map ? static_cast<int>(map->numKeyFrames()) : 0;
	info.reinits = reinits;
	info.map_id = map_id;
	info.metric = map && metric;
	return info;
}

bool VisualOdometry::Impl::track(TrackedFrame& cur, VoFrameInfo& inf)
{
	std::string why;
	bool ok = false;
	if (has_velocity) ok = tracker.withMotionModel(cur, last, velocity, why);
	const char* how = "motion model";
	if (!ok)
	{
		KeyFrame* ref = (last.ref_kf && !last.ref_kf->bad) ? last.ref_kf : last_kf;
		const SE3 start = has_velocity ? velocity * last.Tcw : last.Tcw;
		ok = ref && tracker.withReferenceKeyFrame(cur, ref, start, why);
		how = "reference keyframe";
	}
	if (!ok)
	{
		inf.reason = why;
		return false;
	}
	const int inliers = tracker.withLocalMap(cur);
	inf.matches = inliers;
	const TrackingOptions& o = opt.tracking;
	const bool weak = inliers < o.min_local_inliers;
	if (weak && (o.min_weak_inliers == 0 || inliers < o.min_weak_inliers || weak_frames >= o.max_weak_frames || inliers <= o.keyframe_min_inliers))
	{
		inf.reason = "local map: " + std::to_string(inliers) + " inliers (< " + std::to_string(o.min_local_inliers) + ")";
		return false;
	}
	weak_frames = weak ? weak_frames + 1 : 0;
	cur.has_pose = true;
	inf.reason = weak ? std::string(how) + "; weak: " + std::to_string(inliers) + " inliers, keyframe" : how;
	// No keyframe while the last one's mapping is pending (ORB-SLAM: while local mapping is busy),
	// unless tracking is weak: then the pending BA is applied now, as ORB-SLAM interrupts its BA. At
	// 12 m/s past close foliage the points go out of view within 2-3 frames (doc/VO.md "Fast foliage").
	if (weak || tracker.needKeyFrame(inliers, cur.ref_kf, cur.index - last_kf_frame, map->numKeyFrames()))
	{
		if (mapper->pending() && (weak || inliers < o.keyframe_interrupt_inliers)) addFinished(inf, mapper->finish());
		if (!mapper->pending()) insertKeyFrame(cur, inf);
	}
	velocity = cur.Tcw * last.Tcw.inverse();
	has_velocity = true;
	return true;
}

void VisualOdometry::Impl::insertKeyFrame(TrackedFrame& cur, VoFrameInfo& inf)
{
	const auto t0 = SteadyClock::now();
	KeyFrame* kf = map->addKeyFrame(cur.index, cur.t, cur.feat, cur.Tcw);
	for (std::size_t i = 0; i < cur.size(); ++i)
		if (cur.points[i] && !cur.points[i]->bad) kf->points[i] = cur.points[i];
	const MappingStats st = mapper->process(kf, cur.index + opt.mapping.mapping_delay, mapping_thread);
	for (const char* stage : {"triangulate", "fuse", "ba", "other"}) inf.mapping_ms.add(stage, st.ms.ms(stage));
	inf.new_points = st.new_points;
	if (opt.mapping.mapping_delay == 0 && mapper->pending()) addFinished(inf, mapper->finish());
	cur.Tcw = kf->Tcw;  // the frame is the keyframe: its bundle-adjusted pose once adjusted
	cur.ref_kf = kf;
	last_kf = kf;
	last_kf_frame = cur.index;
	inf.keyframe = true;
	inf.ms.add("mapping", msSince(t0));
}

void VisualOdometry::Impl::continueMapping(VoFrameInfo& inf)
{
	const auto t0 = SteadyClock::now();
	if (mapper->dueFrame() <= inf.index)
		addFinished(inf, mapper->finish());
	else
	{
		mapper->advance();
		inf.mapping_ms.add("ba", msSince(t0));
	}
	inf.ms.add("mapping", msSince(t0));
}

void VisualOdometry::Impl::lose()
{
	if (last.has_pose)
	{
		LostTrack l;
		l.pose = traj_T_map * last.Tcw.inverse();
		l.velocity = has_velocity ? velocity : SE3::Identity();
		l.index = last.index;
		const double d = last_kf ? last_kf->medianDepth() : 0;
		l.median_depth = d > 0 ? d : 1.0;
		lost = l;
	}
	last = TrackedFrame();
	mapper.reset();
	map.reset();
	last_kf = nullptr;
	has_velocity = false;
	weak_frames = 0;
	init.reset();
	state = VoState::Lost;
}
}  // namespace vlo::vo
