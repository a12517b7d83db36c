#include <vlo/loop/place_recognition.h>

#include <algorithm>
#include <utility>

namespace vlo::loop
{
std::optional<PlaceCandidate> PlaceDatabase::query(const ScanContext& sc, std::size_t eligible) const
{
	const Eigen::VectorXd key = ringKey(sc);
	std::vector<std::pair<double, std::size_t>> by_key;
	by_key.reserve(eligible);
	for (std::size_t i = 0; i < eligible; ++i) by_key.emplace_back((keys_[i] - key).squaredNorm(), i);
	const std::size_t n = std::min(by_key.size(), static_cast<std::size_t>(params_.candidates));
	std::partial_sort(by_key.begin(), by_key.begin() + static_cast<std::ptrdiff_t>(n), by_key.end());

	std::optional<PlaceCandidate> best;
	for (std::size_t c = 0; c < n; ++c)
	{
		const std::size_t i = by_key[c].second;
		const DescriptorMatch m = compareScanContexts(sc, contexts_[i]);
		if (m.distance < params_.max_distance && (!best || m.distance < best->match.distance)) best = PlaceCandidate{i, m};
	}
	return best;
}

std::optional<PlaceCandidate> PlaceDatabase::addAndQuery(const ScanPoints& points, double path)
{
	ScanContext sc = makeScanContext(points, params_.descriptor);
	// Paths grow with the index: the places left long enough ago are a prefix.
	const auto eligible = static_cast<std::size_t>(
		std::upper_bound(paths_.begin(), paths_.end(), path - params_.min_revisit_path) - paths_.begin());
	std::optional<PlaceCandidate> best = query(sc, eligible);
	if (params_.query_shift > 0)
		for (const double y : {params_.query_shift, -params_.query_shift})
		{
			std::optional<PlaceCandidate> shifted = query(makeScanContext(points, params_.descriptor, y), eligible);
			if (shifted && (!best || shifted->match.distance < best->match.distance))
			{
				best = shifted;
				best->match.viewpoint_y = y;
			}
		}
	keys_.push_back(ringKey(sc));
	contexts_.push_back(std::move(sc));
	paths_.push_back(path);
	return best;
}
}  // namespace vlo::loop
