#pragma once
// A keyframe's local bundle adjustment taken off the tracking path, entering the map at a fixed frame:
// the window is copied out of the map when the keyframe is made (snapshotBundle), solved on a thread
// of its own, or without one when its result is due, and written back (applyBundle) when the due
// frame starts. Tracking of the frames in between reads the map as it was and the solve reads only
// its copy, so nothing is shared; and as the result enters at the same frame whether a thread solved
// it or not, one and two threads give the same outputs.
#include <vlo/vo/bundle_problem.h>

#include <future>
#include <memory>

namespace vlo::vo
{
struct BundleSolverSettings
{
	int iterations = 5, refine_iterations = 10;
	double chi2 = 5.991;
};

class BundleJob
{
   public:
	/// Snapshots w now; solves it on a thread when `threaded`, else in apply().
	BundleJob(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr, const BundleSolverSettings& s,
		long due_frame, bool threaded);
	/// Waits for the solve (its result is dropped).
	~BundleJob();
	BundleJob(const BundleJob&) = delete;
	BundleJob& operator=(const BundleJob&) = delete;

	long dueFrame() const { return due_; }
	/// The map was scaled by s (about any point) since the snapshot: so is the result when applied.
	void scale(double s) { scale_ *= s; }
	/// Waits for (or runs) the solve and writes the result into the map. Once only.
	BundleStats apply();

   private:
	BundleWindow window_;
	std::unique_ptr<BundleProblem> problem_;
	long due_;
	double scale_ = 1;
	std::future<void> solved_;  // last: waited for before the problem goes
};
}  // namespace vlo::vo
