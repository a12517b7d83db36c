#include <vlo/core/stopwatch.h>
#include <vlo/vo/local_mapper.h>

#include <algorithm>

namespace vlo::vo
{
LocalMapper::LocalMapper(Map& map, const PinholeCamera& cam, const ScalePyramid& pyr, const MappingOptions& opt,
	const TrackingOptions& topt)
	: map_(map), cam_(cam), pyr_(pyr), opt_(opt), topt_(topt), ctx_{cam, pyr, topt}
{
}

MappingStats LocalMapper::process(KeyFrame* kf, long due_frame, bool threaded)
{
	MappingStats st;
	auto t = SteadyClock::now();
	attach(kf);
	st.culled_points = cullRecentPoints(kf);
	st.ms.add("other", lapMs(t));
	st.new_points = createPoints(kf);
	st.ms.add("triangulate", lapMs(t));
	st.fused = fuseNeighbours(kf);
	st.ms.add("fuse", lapMs(t));
	window_ = localWindow(kf, opt_.max_ba_keyframes);
	if (opt_.local_ba)
	{
		const BundleSolverSettings s{opt_.ba_iterations, opt_.ba_refine_iterations, topt_.chi2};
		job_ = std::make_unique<BundleJob>(window_, cam_, pyr_, s, due_frame, threaded);
		job_kf_ = kf;
		st.ms.add("ba", lapMs(t));
	}
	else
	{
		cullAround(kf, st);
		st.ms.add("other", lapMs(t));
	}
	return st;
}

MappingStats LocalMapper::finish()
{
	MappingStats st;
	if (!job_) return st;
	auto t = SteadyClock::now();
	st.ba = job_->apply();
	job_.reset();
	st.ms.add("ba", lapMs(t));
	cullAround(job_kf_, st);
	job_kf_ = nullptr;
	st.ms.add("other", lapMs(t));
	return st;
}

void LocalMapper::cullAround(KeyFrame* kf, MappingStats& st)
{
	st.culled_keyframes = cullKeyFrames(kf);
	std::vector<KeyFrame*> in_use = window_.local;  // and the keyframe's covisible ones
	for (KeyFrame* k : kf->bestCovisibles(-1)) in_use.push_back(k);
	st.dropped_keyframes = map_.dropOldKeyFrames(static_cast<std::size_t>(opt_.keep_keyframes), in_use);
	scrub();
}

void LocalMapper::attach(KeyFrame* kf)
{
	for (std::size_t i = 0; i < kf->points.size(); ++i)
	{
		MapPoint* mp = kf->points[i];
		if (!mp) continue;
		if (mp->bad || mp->indexIn(kf) >= 0)  // gone, or the same point on two keypoints
		{
			kf->points[i] = nullptr;
			continue;
		}
		mp->addObservation(kf, static_cast<int>(i));
		mp->updateNormalAndDepth(pyr_);
		mp->updateDescriptor();
	}
	kf->updateConnections(opt_.min_covisibility);
}

int LocalMapper::cullRecentPoints(const KeyFrame* kf)
{
	int culled = 0;
	std::vector<MapPoint*> keep;
	for (MapPoint* mp : recent_)
	{
		if (mp->bad) continue;
		const long age = kf->id - mp->first_kf_id;
		if (mp->foundRatio() < opt_.min_found_ratio || (age >= 2 && mp->numObservations() <= opt_.culling_min_observations))
		{
			mp->setBad();
			++culled;
		}
		else if (age < 3)
			keep.push_back(mp);  // older points have proven themselves
	}
	recent_ = std::move(keep);
	return culled;
}

int LocalMapper::fuseNeighbours(KeyFrame* kf)
{
	// Direct neighbours and the best few of theirs.
	std::vector<KeyFrame*> targets;
	kf->mark_fuse = kf->id;
	for (KeyFrame* n : kf->bestCovisibles(opt_.fuse_neighbours))
		if (n->mark_fuse != kf->id) n->mark_fuse = kf->id, targets.push_back(n);
	for (std::size_t i = 0, n0 = targets.size(); i < n0; ++i)
		for (KeyFrame* n2 : targets[i]->bestCovisibles(5))
			if (n2->mark_fuse != kf->id) n2->mark_fuse = kf->id, targets.push_back(n2);

	int fused = 0;
	for (KeyFrame* t : targets)
	{
		const std::vector<MapPoint*> mine = kf->points;  // fusion edits kf->points
		fused += fuse(t, mine, opt_.fuse_radius, ctx_);
	}
	std::vector<MapPoint*> theirs;
	for (KeyFrame* t : targets)
		for (MapPoint* mp : t->points)
			if (mp && !mp->bad && mp->mark_fuse != kf->id)
			{
				mp->mark_fuse = kf->id;
				theirs.push_back(mp);
			}
	fused += fuse(kf, theirs, opt_.fuse_radius, ctx_);
	for (MapPoint* mp : kf->points)
		if (mp && !mp->bad)
		{
			mp->updateDescriptor();
			mp->updateNormalAndDepth(pyr_);
		}
	kf->updateConnections(opt_.min_covisibility);
	return fused;
}

int LocalMapper::cullKeyFrames(KeyFrame* kf)
{
	int culled = 0;
	const long first_id = map_.keyFrames().front()->id;
	for (KeyFrame* k : kf->bestCovisibles(-1))
	{
		if (k->id == first_id || k->bad) continue;  // the map origin stays
		int n = 0, redundant = 0;
		for (std::size_t i = 0; i < k->points.size(); ++i)
		{
			const MapPoint* mp = k->points[i];
			if (!mp || mp->bad) continue;
			++n;
			if (mp->numObservations() <= opt_.redundant_observers) continue;
			const int level = k->key(static_cast<int>(i)).octave;
			int seen = 0;
			for (const auto& o : mp->observations())
			{
				if (o.kf == k) continue;
				if (o.kf->key(o.idx).octave <= level + 1 && ++seen >= opt_.redundant_observers) break;
			}
			if (seen >= opt_.redundant_observers) ++redundant;
		}
		if (n > 0 && redundant > opt_.redundant_ratio * n)
		{
			k->setBad();
			++culled;
		}
	}
	return culled;
}

void LocalMapper::scrub()
{
	recent_.erase(std::remove_if(recent_.begin(), recent_.end(), [](const MapPoint* p) { return p->bad; }), recent_.end());
	auto badKf = [](const KeyFrame* k) { return k->bad; };
	window_.local.erase(std::remove_if(window_.local.begin(), window_.local.end(), badKf), window_.local.end());
	window_.fixed.erase(std::remove_if(window_.fixed.begin(), window_.fixed.end(), badKf), window_.fixed.end());
	window_.points.erase(std::remove_if(window_.points.begin(), window_.points.end(), [](const MapPoint* p) { return p->bad; }),
		window_.points.end());
	if (window_.anchor && window_.anchor->bad) window_.anchor = nullptr;
	for (KeyFrame* k : window_.local)
		if (!window_.anchor || k->id < window_.anchor->id) window_.anchor = k;
}
}  // namespace vlo::vo
