#include <vlo/vo/matcher.h>

#include <algorithm>
#include <cmath>

namespace vlo::vo
{
void RotationHistogram::add(float angle1, float angle2, int match)
{
	float rot = angle1 - angle2;
	if (rot < 0) rot += 360.f;
	int bin = static_cast<int>(std::lround(rot * kBins / 360.f));
	if (bin >= kBins) bin = 0;
	bins_[bin].push_back(match);
}

std::vector<int> RotationHistogram::rejected() const
{
	int order[kBins];
	for (int i = 0; i < kBins; ++i) order[i] = i;
	std::stable_sort(order, order + kBins, [&](int a, int b) { return bins_[a].size() > bins_[b].size(); });
	const std::size_t top = bins_[order[0]].size();
	std::vector<char> keep(kBins, 0);
	keep[order[0]] = 1;
	for (int k = 1; k < 3; ++k)
		if (bins_[order[k]].size() > 0.1 * top) keep[order[k]] = 1;
	std::vector<int> out;
	for (int b = 0; b < kBins; ++b)
		if (!keep[b]) out.insert(out.end(), bins_[b].begin(), bins_[b].end());
	return out;
}
}  // namespace vlo::vo
