#include <vlo/vo/bundle_job.h>

namespace vlo::vo
{
BundleJob::BundleJob(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr,
	const BundleSolverSettings& s, long due_frame, bool threaded)
	: window_(w), problem_(std::make_unique<BundleProblem>(snapshotBundle(w, cam, pyr))), due_(due_frame)
{
	BundleProblem* p = problem_.get();
	solved_ = std::async(threaded ? std::launch::async : std::launch::deferred,
		[p, s] { solveBundle(*p, s.iterations, s.refine_iterations, s.chi2); });
}

BundleJob::~BundleJob()
{
	if (solved_.valid()) solved_.wait();
}

BundleStats BundleJob::apply()
{
	solved_.get();
	return applyBundle(window_, *problem_, scale_);
}
}  // namespace vlo::vo
