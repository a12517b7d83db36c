// Motion source "metric_mono" (the paper's front end): a monocular VO kept metric by a scale
// corrector. Per frame the VO tracks, the corrector estimates the scale of its motion from the
// previous frame's scan and decides on a correction, which this class applies to the VO's map
// before the next frame, and the metric path turns the result into the vehicle's motion in metres.
#include "metric_vo_path.h"

#include <vlo/core/error.h>
#include <vlo/core/stopwatch.h>
#include <vlo/kernel/motion_source.h>
#include <vlo/kernel/scale_correction.h>
#include <vlo/kernel/visual_odometry.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace vlo::pipeline
{
namespace
{
/// How far the motion can be trusted, from the VO's step and the scale corrector's estimate.
kernel::MotionQuality quality(const kernel::VisualOdometryStep& step, const kernel::ScaleCorrection& correction)
{
	kernel::MotionQuality q;
	if (step.tracked) q.tracked = *step.tracked;
	q.length_error = correction.relative_error;
	return q;
}

class MetricMonoVo : public kernel::MotionSource
{
   public:
	void configure(kernel::RunConfig& config, const kernel::MotionSourceSetup& setup) override
	{
		const std::string where = config.where("pipeline", "visual_odometry");
		auto vo = kernel::registry<kernel::VisualOdometryModule>().create(setup.visual_odometry, where);
		vo_.reset(dynamic_cast<kernel::MonocularVisualOdometry*>(vo.get()));
		if (!vo_) failInput(where, "'" + setup.visual_odometry + "' is not a monocular VO, which motion_source = metric_mono needs (a metric VO: motion_source = visual)");
		vo.release();
		vo_->configure(config);
		vo_->useThreads(setup.threads);
		scale_ = kernel::registry<kernel::ScaleCorrectionModule>().create(
			setup.scale_correction, config.where("pipeline", "scale_correction"));
		scale_->configure(config, setup.snapshot_every);
	}

	std::optional<kernel::MotionGuess> process(std::shared_ptr<const Frame> frame, kernel::FrameTable& table) override
	{
		auto t0 = SteadyClock::now();
		const kernel::VisualOdometryStep step = vo_->process(*frame, table);
		table.set("ms_vo", lapMs(t0), 2);
		const kernel::ScaleCorrection correction = scale_->process(prev_.get(), *frame, step, table);
		// A correction comes only for a frame tracked in a map, which the VO can scale.
		if (correction.apply() && !vo_->rescale(correction.factor, correction.kind == kernel::ScaleCorrection::Kind::Initial))
			throw std::logic_error("frame " + std::to_string(frame->index) + ": the VO had no map to scale");
		if (!path_) path_.emplace(frame->rig.vehicle_T_camera);
		const auto motion = path_->update(frame->t, step, correction);
		prev_ = std::move(frame);
		if (!motion) return std::nullopt;
		return kernel::MotionGuess{*motion, quality(step, correction)};
	}

	Trajectory trajectory() const override { return path_ ? path_->trajectory() : Trajectory{}; }
	std::string label() const override { return "scale-corrected VO"; }
	void writeSnapshots(const std::string& dir) const override { scale_->writeSnapshots(dir); }
	std::vector<std::pair<std::string, double>> figures() const override { return scale_->figures(); }

   private:
	std::unique_ptr<kernel::MonocularVisualOdometry> vo_;
	std::unique_ptr<kernel::ScaleCorrectionModule> scale_;
	std::optional<MetricVoPath> path_;
	std::shared_ptr<const Frame> prev_;  ///< the previous frame, shared with the run loop
};
VLO_REGISTER_MODULE(kernel::MotionSource, "metric_mono", MetricMonoVo);
}  // namespace
}  // namespace vlo::pipeline
