#include <vlo/vo/bundle_job.h>

namespace vlo::vo
{
BundleJob::BundleJob(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr,
	const BundleSolverSettings& s, long due_frame, bool threaded)
	: window_(w), problem_(std::make_unique<BundleProblem>(snapshotBundle(w, cam, pyr))), settings_(s), due_(due_frame)
{
	if (threaded)
		solved_ = std::async(std::launch::async, [this] {
			runRobust();
			runRefine();
		});
}

BundleJob::~BundleJob()
{
	if (solved_.valid()) solved_.wait();
}

void BundleJob::advance()
{
	if (!solved_.valid() && passes_ == 0) runRobust();
}

BundleStats BundleJob::apply()
{
	if (solved_.valid())
		solved_.get();
	else
	{
		advance();
		runRefine();
	}
	return applyBundle(window_, *problem_, scale_);
}

void BundleJob::runRobust()
{
	solveRobust(*problem_, settings_.iterations, settings_.chi2);
	++passes_;
}

void BundleJob::runRefine()
{
	solveRefine(*problem_, settings_.refine_iterations, settings_.chi2);
	++passes_;
}
}  // namespace vlo::vo
