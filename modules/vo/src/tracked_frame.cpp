#include <vlo/vo/map_point.h>
#include <vlo/vo/tracked_frame.h>

namespace vlo::vo
{
int TrackedFrame::inliers() const
{
	int n = 0;
	for (std::size_t i = 0; i < points.size(); ++i)
		if (points[i] && !outlier[i]) ++n;
	return n;
}

void TrackedFrame::resolvePoints()
{
	for (auto& p : points)
	{
		if (!p || !p->bad) continue;
		MapPoint* r = p->resolved();
		p = (r && !r->bad) ? r : nullptr;
	}
}
}  // namespace vlo::vo
