#include <vlo/io/frame_pairing.h>

#include <cmath>

namespace vlo::io
{
PairStep pairStep(const std::deque<double>& images, const std::deque<double>& scans, double tolerance, bool no_more)
{
	if (images.empty() && scans.empty()) return no_more ? PairStep::Done : PairStep::NeedMore;
	if (images.empty()) return no_more ? PairStep::SkipScan : PairStep::NeedMore;
	if (scans.empty()) return no_more ? PairStep::SkipImage : PairStep::NeedMore;
	const double ti = images.front(), ts = scans.front();
	if (ts < ti - tolerance) return PairStep::SkipScan;
	if (ti < ts - tolerance) return PairStep::SkipImage;
	// Within tolerance. The later head is certainly the earlier head's nearest partner (later
	// observations are farther still); the earlier head may lose to its own successor.
	if (ti <= ts)
	{
		if (images.size() < 2) return no_more ? PairStep::Pair : PairStep::NeedMore;
		return std::abs(images[1] - ts) < ts - ti ? PairStep::SkipImage : PairStep::Pair;
	}
	if (scans.size() < 2) return no_more ? PairStep::Pair : PairStep::NeedMore;
	return std::abs(scans[1] - ti) < ti - ts ? PairStep::SkipScan : PairStep::Pair;
}
}  // namespace vlo::io
