#include <vlo/vo/map_initializer.h>
#include <vlo/vo/optimizer.h>

namespace vlo::vo
{
MapInitializer::MapInitializer(const PinholeCamera& cam, const ScalePyramid& pyr, const InitOptions& opt,
	const TrackingOptions& topt, const MappingOptions& mopt)
	: cam_(cam), pyr_(pyr), opt_(opt), mopt_(mopt), ctx_{cam, pyr, topt}
{
}

void MapInitializer::setReference(const TrackedFrame& f)
{
	ref_ = f;
	prev_.resize(f.size());
	for (std::size_t i = 0; i < f.size(); ++i) prev_[i] = Vec2(f.feat->keys[i].pt.x, f.feat->keys[i].pt.y);
}

InitResult MapInitializer::feed(const TrackedFrame& f)
{
	InitResult r;
	const int nf = static_cast<int>(f.size());
	if (nf < opt_.min_features)
	{
		ref_.reset();
		r.reason = "too few features (" + std::to_string(nf) + " < " + std::to_string(opt_.min_features) + ")";
		return r;
	}
	if (!ref_)
	{
		setReference(f);
		r.reason = "initialisation reference set";
		return r;
	}
	const auto m12 = searchForInitialization(*ref_->feat, *f.feat, prev_, opt_.search_radius, opt_.match_ratio, opt_.max_level, ctx_);
	std::vector<Vec2> x1, x2;
	std::vector<std::size_t> pair_of;  // reference keypoint of each correspondence
	for (std::size_t i = 0; i < m12.size(); ++i)
		if (m12[i] >= 0)
		{
			const auto& a = ref_->feat->keys[i].pt;
			const auto& b = f.feat->keys[static_cast<std::size_t>(m12[i])].pt;
			x1.emplace_back(a.x, a.y);
			x2.emplace_back(b.x, b.y);
			pair_of.push_back(i);
		}
	r.matches = static_cast<int>(x1.size());
	if (r.matches < opt_.min_matches)
	{
		r.reason = "too few matches with the reference (" + std::to_string(r.matches) + " < " +
			std::to_string(opt_.min_matches) + "): new reference";
		setReference(f);
		return r;
	}
	const TwoViewResult tv = reconstructTwoView(cam_, x1, x2, opt_);
	if (!tv.ok)
	{
		r.reason = tv.reason + " with " + std::to_string(r.matches) + " matches";
		return r;
	}
	r = buildMap(f, tv, m12, pair_of);
	if (!r.ok) setReference(f);
	return r;
}

InitResult MapInitializer::buildMap(const TrackedFrame& cur, const TwoViewResult& tv, const std::vector<int>& m12,
	const std::vector<std::size_t>& pair_of)
{
	InitResult r;
	r.matches = static_cast<int>(pair_of.size());
	r.map = std::make_unique<Map>();
	KeyFrame* k1 = r.map->addKeyFrame(ref_->index, ref_->t, ref_->feat, SE3::Identity());
	KeyFrame* k2 = r.map->addKeyFrame(cur.index, cur.t, cur.feat, tv.T21);
	BundleWindow w;
	for (std::size_t c = 0; c < pair_of.size(); ++c)
	{
		if (!tv.good[c]) continue;
		const int i1 = static_cast<int>(pair_of[c]), i2 = m12[pair_of[c]];
		w.points.push_back(r.map->addPointSeenBy(tv.points[c], k2, k1, i1, k2, i2, pyr_));
	}
	k1->updateConnections(mopt_.min_covisibility);
	k2->updateConnections(mopt_.min_covisibility);
	w.local = {k1, k2};
	w.anchor = k1;
	bundleAdjust(w, cam_, pyr_, opt_.ba_iterations, 0, ctx_.opt.chi2, k1);

	const double median = k1->medianDepth();
	const int tracked = k2->trackedPoints(1);
	if (median <= 0 || tracked < opt_.min_tracked_after_ba)
	{
		r.map.reset();
		r.reason = std::string(1, tv.model) + ": " + std::to_string(tracked) + " points after two-view BA (< " +
			std::to_string(opt_.min_tracked_after_ba) + ")";
		return r;
	}
	// Unit median depth: the arbitrary monocular scale, made the same at every initialisation.
	r.map->scale(1.0 / median);
	r.ok = true;
	r.reason = std::string("initialised (") + tv.model + ", " + std::to_string(tracked) + " points)";
	r.first = k1;
	r.second = k2;
	ref_.reset();
	return r;
}
}  // namespace vlo::vo
