#pragma once
// A keyframe's local bundle adjustment taken off the tracking path, entering the map at a fixed frame:
// the window is copied out of the map when the keyframe is made (snapshotBundle), solved on a thread
// of its own or, without one, in two pieces (the robust pass on advance(), at the frame after the
// keyframe's; the refine pass when the result is due: with a due frame two after the keyframe no
// frame carries the whole solve), and written back (applyBundle) when the due frame
// starts. Tracking of the frames in between reads the map as it was and the solve reads only its
// copy, so nothing is shared; and as the result enters at the same frame whether a thread solved it
// or not, one and two threads give the same outputs.
#include <vlo/vo/bundle_problem.h>

#include <atomic>
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
	/// Snapshots w now; solves it on a thread when `threaded`, else in advance() and apply().
	BundleJob(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr, const BundleSolverSettings& s,
		long due_frame, bool threaded);
	/// Waits for the solve (its result is dropped).
	~BundleJob();
	BundleJob(const BundleJob&) = delete;
	BundleJob& operator=(const BundleJob&) = delete;

	long dueFrame() const { return due_; }
	/// The map was scaled by s (about any point) since the snapshot: so is the result when applied.
	void scale(double s) { scale_ *= s; }
	/// Without a thread: runs the solve's robust pass, unless it ran already.
	void advance();
	/// Waits for (or runs what is left of) the solve and writes the result into the map. Once only.
	BundleStats apply();
	/// Passes of the solve done so far (0-2: robust, refine).
	int passesDone() const { return passes_; }

   private:
	void runRobust();
	void runRefine();

	BundleWindow window_;
	std::unique_ptr<BundleProblem> problem_;
	BundleSolverSettings settings_;
	long due_;
	double scale_ = 1;
	std::atomic<int> passes_{0};
	std::future<void> solved_;  // last: waited for before the problem goes
};
}  // namespace vlo::vo
