// The covisibility graph: keyframes linked by the number of map points they share.
#include <vlo/vo/keyframe.h>
#include <vlo/vo/map_point.h>

#include <algorithm>
#include <unordered_map>

namespace vlo::vo
{
void KeyFrame::updateConnections(int min_weight)
{
	std::unordered_map<KeyFrame*, int> counts;
	for (const MapPoint* p : points)
	{
		if (!p || p->bad) continue;
		for (const auto& o : p->observations())
			if (o.kf != this && !o.kf->bad) ++counts[o.kf];
	}
	// Sorted by id so that ties and the order of updates do not depend on addresses.
	std::vector<std::pair<KeyFrame*, int>> all(counts.begin(), counts.end());
	std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first->id < b.first->id; });
	std::vector<std::pair<KeyFrame*, int>> kept;
	const std::pair<KeyFrame*, int>* best = nullptr;
	for (const auto& e : all)
	{
		if (!best || e.second > best->second) best = &e;
		if (e.second >= min_weight) kept.push_back(e);
	}
	if (kept.empty() && best) kept.push_back(*best);  // never leave a keyframe unconnected

	for (const auto& [kf, w] : connections_)
		if (std::none_of(kept.begin(), kept.end(), [&](const auto& e) { return e.first == kf; })) kf->eraseConnection(this);
	for (const auto& [kf, w] : kept) kf->addConnection(this, w);
	connections_ = std::move(kept);
	sortConnections();
}

void KeyFrame::addConnection(KeyFrame* kf, int w)
{
	for (auto& e : connections_)
		if (e.first == kf)
		{
			e.second = w;
			sortConnections();
			return;
		}
	connections_.emplace_back(kf, w);
	sortConnections();
}

void KeyFrame::eraseConnection(KeyFrame* kf)
{
	connections_.erase(std::remove_if(connections_.begin(), connections_.end(), [&](const auto& e) { return e.first == kf; }),
		connections_.end());
}

int KeyFrame::weight(const KeyFrame* kf) const
{
	for (const auto& e : connections_)
		if (e.first == kf) return e.second;
	return 0;
}

std::vector<KeyFrame*> KeyFrame::bestCovisibles(int n) const
{
	std::vector<KeyFrame*> out;
	for (const auto& e : connections_)
	{
		if (n >= 0 && static_cast<int>(out.size()) >= n) break;
		if (!e.first->bad) out.push_back(e.first);
	}
	return out;
}

void KeyFrame::sortConnections()
{
	std::sort(connections_.begin(), connections_.end(), [](const auto& a, const auto& b) {
		return a.second != b.second ? a.second > b.second : a.first->id < b.first->id;
	});
}
}  // namespace vlo::vo
