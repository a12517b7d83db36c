#include <vlo/vo/keyframe.h>
#include <vlo/vo/map_point.h>

#include <algorithm>

namespace vlo::vo
{
KeyFrame::KeyFrame(long id_, long frame_index_, double t_, std::shared_ptr<const Features> f, const SE3& T)
	: id(id_), frame_index(frame_index_), t(t_), Tcw(T), feat(std::move(f)), points(feat->size(), nullptr)
{
}

int KeyFrame::trackedPoints(int min_obs) const
{
	int n = 0;
	for (const MapPoint* p : points)
		if (p && !p->bad && p->numObservations() >= min_obs) ++n;
	return n;
}

double KeyFrame::medianDepth() const
{
	std::vector<double> z;
	for (const MapPoint* p : points)
		if (p && !p->bad) z.push_back((Tcw * p->pos).z());
	if (z.empty()) return 0;
	std::nth_element(z.begin(), z.begin() + static_cast<long>(z.size() / 2), z.end());
	return z[z.size() / 2];
}

void KeyFrame::setBad()
{
	for (MapPoint*& p : points)
	{
		MapPoint* mp = p;
		p = nullptr;
		if (mp && !mp->bad) mp->eraseObservation(this);
	}
	for (const auto& [kf, w] : connections_) kf->eraseConnection(this);
	connections_.clear();
	bad = true;
}
}  // namespace vlo::vo
