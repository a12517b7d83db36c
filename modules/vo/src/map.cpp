#include <vlo/vo/map.h>

#include <algorithm>

namespace vlo::vo
{
KeyFrame* Map::addKeyFrame(long frame_index, double t, std::shared_ptr<const Features> f, const SE3& Tcw)
{
	kfs_.push_back(std::make_unique<KeyFrame>(next_kf_++, frame_index, t, std::move(f), Tcw));
	return kfs_.back().get();
}

MapPoint* Map::addPoint(const Vec3& pos, KeyFrame* ref)
{
	points_.push_back(std::make_unique<MapPoint>(next_point_++, pos, ref));
	return points_.back().get();
}

MapPoint* Map::addPointSeenBy(
	const Vec3& pos, KeyFrame* ref, KeyFrame* a, int ia, KeyFrame* b, int ib, const ScalePyramid& pyr)
{
	MapPoint* mp = addPoint(pos, ref);
	mp->addObservation(a, ia);
	mp->addObservation(b, ib);
	a->points[static_cast<std::size_t>(ia)] = mp;
	b->points[static_cast<std::size_t>(ib)] = mp;
	mp->updateDescriptor();
	mp->updateNormalAndDepth(pyr);
	return mp;
}

std::vector<KeyFrame*> Map::keyFrames() const
{
	std::vector<KeyFrame*> out;
	for (const auto& k : kfs_)
		if (!k->bad) out.push_back(k.get());
	return out;
}

std::size_t Map::numKeyFrames() const
{
	return static_cast<std::size_t>(std::count_if(kfs_.begin(), kfs_.end(), [](const auto& k) { return !k->bad; }));
}

std::size_t Map::numPoints() const
{
	return static_cast<std::size_t>(std::count_if(points_.begin(), points_.end(), [](const auto& p) { return !p->bad; }));
}

std::vector<MapPoint*> Map::points() const
{
	std::vector<MapPoint*> out;
	for (const auto& p : points_)
		if (!p->bad) out.push_back(p.get());
	return out;
}

int Map::dropOldKeyFrames(std::size_t keep_newest, const std::vector<KeyFrame*>& in_use)
{
	const std::vector<KeyFrame*> live = keyFrames();
	if (keep_newest == 0 || live.size() <= keep_newest + 1) return 0;
	int dropped = 0;
	// live[0] is the origin; live[size - keep_newest ...] are the newest.
	for (std::size_t i = 1; i < live.size() - keep_newest; ++i)
		if (std::find(in_use.begin(), in_use.end(), live[i]) == in_use.end())
		{
			live[i]->setBad();
			++dropped;
		}
	return dropped;
}

void Map::collectGarbage()
{
	points_.erase(std::remove_if(points_.begin(), points_.end(), [](const auto& p) { return p->bad; }), points_.end());
	kfs_.erase(std::remove_if(kfs_.begin(), kfs_.end(), [](const auto& k) { return k->bad; }), kfs_.end());
}

void Map::scale(double s)
{
	for (const auto& k : kfs_) k->Tcw.translation() *= s;
	for (const auto& p : points_)
	{
		p->pos *= s;
		p->min_dist *= s;
		p->max_dist *= s;
	}
}
}  // namespace vlo::vo
