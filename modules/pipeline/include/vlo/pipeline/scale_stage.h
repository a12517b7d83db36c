#pragma once
// The scale corrector in the run loop (mode vlo): per frame, the estimate from C(i-1), L(i-1), C(i)
// and the VO's camera motion, the policy's decision, the rescaling of the VO map, and the scale_*
// columns of frames.csv. Keeps the frames chosen for scale snapshots.
#include <vlo/pipeline/metric_vo_path.h>
#include <vlo/pipeline/visual_odometry_module.h>
#include <vlo/scale/policy.h>
#include <vlo/scale/scale_corrector.h>

#include <vector>

namespace vlo
{
struct ScaleSnapshot
{
	Frame prev;  ///< C(i-1) and L(i-1), deep copies
	std::size_t cur_index = 0;
	scale::ScaleEstimate estimate;
};

class ScaleStage
{
   public:
	/// Loads [scale]; `snapshot_every` > 0 keeps every N-th frame's estimate for a snapshot.
	ScaleStage(RunConfig& config, int snapshot_every);

	/// `prev` is the previous frame (nullptr at the first). Rescales `vo` when the policy says so.
	ScaleApplied process(const Frame* prev, const Frame& cur, const VisualOdometryStep& step,
		VisualOdometryModule& vo, FrameTable& table);

	const std::vector<ScaleSnapshot>& snapshots() const { return snapshots_; }
	int estimates() const { return estimates_; }
	int valid() const { return valid_; }
	int corrections() const { return corrections_; }

   private:
	scale::ScaleOptions opt_;
	std::unique_ptr<scale::ScaleCorrector> corrector_;
	std::unique_ptr<scale::ScaleCorrectionPolicy> policy_;
	int snapshot_every_ = 0;
	std::vector<ScaleSnapshot> snapshots_;
	int estimates_ = 0, valid_ = 0, corrections_ = 0;
};
}  // namespace vlo
