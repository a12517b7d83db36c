#pragma once
// The decision rule that pairs two time-ordered sensor streams (camera, LiDAR) by nearest
// timestamp. Pure and streaming: it looks only at the heads of two queues of times.
#include <deque>

namespace vlo::io
{
enum class PairStep
{
	Pair,  ///< the two heads belong together
	SkipImage,  ///< the image head has no partner
	SkipScan,  ///< the scan head has no partner
	NeedMore,  ///< cannot decide until more observations arrive
	Done  ///< both queues empty and nothing more will come
};

/// Each queue holds increasing times. A pair is formed when each head is the other's nearest
/// partner within `tolerance` seconds. With `no_more` set, missing look-ahead counts as absent.
PairStep pairStep(const std::deque<double>& images, const std::deque<double>& scans, double tolerance, bool no_more);
}  // namespace vlo::io
