#include <vlo/vo/keyframe.h>
#include <vlo/vo/map_point.h>

#include <algorithm>

namespace vlo::vo
{
MapPoint::MapPoint(long id_, const Vec3& p, KeyFrame* ref) : id(id_), pos(p), ref_kf(ref), first_kf_id(ref ? ref->id : -1) {}

int MapPoint::indexIn(const KeyFrame* kf) const
{
	for (const auto& o : obs_)
		if (o.kf == kf) return o.idx;
	return -1;
}

void MapPoint::addObservation(KeyFrame* kf, int idx)
{
	if (indexIn(kf) >= 0) return;
	obs_.push_back({kf, idx});
}

void MapPoint::eraseObservation(KeyFrame* kf)
{
	const auto it = std::find_if(obs_.begin(), obs_.end(), [&](const Observation& o) { return o.kf == kf; });
	if (it == obs_.end()) return;
	obs_.erase(it);
	if (ref_kf == kf) ref_kf = obs_.empty() ? nullptr : obs_.front().kf;
	// One view cannot constrain a point (ORB-SLAM drops it at two already; we keep two-view points).
	if (obs_.size() < 2) setBad();
}

void MapPoint::setBad()
{
	bad = true;
	for (const auto& o : obs_)
		if (o.kf->points[static_cast<std::size_t>(o.idx)] == this) o.kf->points[static_cast<std::size_t>(o.idx)] = nullptr;
	obs_.clear();
}

void MapPoint::replaceWith(MapPoint* other)
{
	if (other == this || other == nullptr) return;
	for (const auto& o : obs_)
	{
		auto& slot = o.kf->points[static_cast<std::size_t>(o.idx)];
		if (other->indexIn(o.kf) < 0)
		{
			slot = other;
			other->addObservation(o.kf, o.idx);
		}
		else if (slot == this)
			slot = nullptr;
	}
	obs_.clear();
	other->found += found;
	other->visible += visible;
	other->updateDescriptor();
	bad = true;
	replaced = other;
}

MapPoint* MapPoint::resolved()
{
	MapPoint* p = this;
	for (int guard = 0; p->replaced && guard < 100; ++guard) p = p->replaced;
	return p;
}

void MapPoint::updateDescriptor()
{
	const std::size_t n = obs_.size();
	if (n == 0) return;
	std::vector<const uint8_t*> d(n);
	for (std::size_t i = 0; i < n; ++i) d[i] = obs_[i].kf->feat->descriptor(static_cast<std::size_t>(obs_[i].idx));
	std::vector<int> dist(n * n, 0);
	for (std::size_t i = 0; i < n; ++i)
		for (std::size_t j = i + 1; j < n; ++j) dist[i * n + j] = dist[j * n + i] = hamming(d[i], d[j]);
	int best = 1 << 30;
	std::size_t besti = 0;
	std::vector<int> row(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		std::copy(dist.begin() + static_cast<long>(i * n), dist.begin() + static_cast<long>((i + 1) * n), row.begin());
		std::nth_element(row.begin(), row.begin() + static_cast<long>((n - 1) / 2), row.end());
		const int median = row[(n - 1) / 2];
		if (median < best) best = median, besti = i;
	}
	std::copy(d[besti], d[besti] + 32, desc.begin());
}

void MapPoint::updateNormalAndDepth(const ScalePyramid& pyr)
{
	if (obs_.empty() || ref_kf == nullptr) return;
	Vec3 n = Vec3::Zero();
	for (const auto& o : obs_) n += (pos - o.kf->centre()).normalized();
	normal = n.normalized();
	const int ref_idx = indexIn(ref_kf);
	if (ref_idx < 0) return;
	const double dist = (pos - ref_kf->centre()).norm();
	const int level = ref_kf->key(ref_idx).octave;
	max_dist = dist * pyr.scale[static_cast<std::size_t>(level)];
	min_dist = max_dist / pyr.scale.back();
}
}  // namespace vlo::vo
