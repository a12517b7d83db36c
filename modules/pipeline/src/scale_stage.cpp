#include <vlo/pipeline/scale_stage.h>

namespace vlo
{
ScaleStage::ScaleStage(RunConfig& config, int snapshot_every) : snapshot_every_(snapshot_every)
{
	config.load(opt_, "scale");
	corrector_ = std::make_unique<scale::ScaleCorrector>(opt_);  // validates the options
	policy_ = std::make_unique<scale::ScaleCorrectionPolicy>(opt_);
}

ScaleApplied ScaleStage::process(
	const Frame* prev, const Frame& cur, const VisualOdometryStep& step, VisualOdometryModule& vo, FrameTable& table)
{
	if (step.new_map) policy_->reset();  // a fresh map has an arbitrary scale again
	ScaleApplied applied;
	if (!step.camera_motion || !prev || !prev->has_scan || !prev->has_image)
	{
		table.set("scale_decision", std::string(step.camera_motion ? "no previous scan" : "no VO motion"));
		return applied;
	}
	// The estimator wants T_{C(i-1)}^{C(i)}; the VO gives the current camera in the previous one.
	const scale::ScaleEstimate e = corrector_->estimate(*prev, cur, step.camera_motion->inverse());
	++estimates_;
	valid_ += e.valid ? 1 : 0;
	const scale::ScaleDecision d = policy_->decide(e);
	std::string decision = scale::toString(d.kind);
	if (d.apply())
	{
		const bool initial = d.kind == scale::ScaleDecision::Kind::Initial;
		if (vo.rescale(d.factor, initial))
		{
			applied = {d.factor, initial};
			corrections_ += initial ? 0 : 1;
		}
		else
		{
			policy_->reset();  // the VO had nothing to scale: try again at the next estimate
			decision = "not applied (no VO map)";
		}
	}
	else
		decision += std::string(": ") + d.why;

	table.set("scale_reason", std::string(scale::toString(e.reason)));
	table.set("scale_s", e.scale, 4);
	table.set("scale_spread", e.spread, 4);
	table.set("scale_projected", static_cast<long long>(e.counts.projected));
	table.set("scale_selected", static_cast<long long>(e.counts.selected));
	table.set("scale_tracked", static_cast<long long>(e.counts.tracked));
	table.set("scale_culled_kept", static_cast<long long>(e.counts.gradient_kept));
	table.set("scale_triangulated", static_cast<long long>(e.counts.triangulated));
	table.set("scale_inliers", static_cast<long long>(e.counts.inliers));
	table.set("scale_decision", decision);
	table.set("scale_applied", applied.factor, 4);
	table.set("scale_cumulative", policy_->cumulative(), 4);
	table.set("ms_scale", e.ms.total, 2);

	if (snapshot_every_ > 0 && cur.index % snapshot_every_ == 0)
	{
		Frame copy = *prev;
		copy.image = prev->image.makeDeepCopy();
		snapshots_.push_back({std::move(copy), cur.index, e});
	}
	return applied;
}
}  // namespace vlo
