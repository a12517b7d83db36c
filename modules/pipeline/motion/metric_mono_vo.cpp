// Motion source "metric_mono" (the paper's front end): a monocular VO kept metric by a scale
// corrector. Per frame the VO tracks, the corrector estimates the scale of its motion from the
// previous frame's scan and rescales the VO's map through the VO, and the metric path turns the
// result into the vehicle's motion in metres. The rescaling feedback stays inside this class.
#include "metric_vo_path.h"

#include <vlo/core/error.h>
#include <vlo/core/stopwatch.h>
#include <vlo/kernel/motion_source.h>
#include <vlo/kernel/scale_correction.h>
#include <vlo/kernel/visual_odometry.h>

namespace vlo
{
namespace
{
class MetricMonoVo : public MotionSource
{
   public:
	void configure(RunConfig& config, const MotionSourceSetup& setup) override
	{
		const std::string where = config.where("pipeline", "visual_odometry");
		auto vo = registry<VisualOdometryModule>().create(setup.visual_odometry, where);
		vo_.reset(dynamic_cast<MonocularVisualOdometry*>(vo.get()));
		if (!vo_) failInput(where, "'" + setup.visual_odometry + "' is not a monocular VO, which motion_source = metric_mono needs (a metric VO: motion_source = visual)");
		vo.release();
		vo_->configure(config);
		vo_->useThreads(setup.threads);
		scale_ = registry<ScaleCorrectionModule>().create(
			setup.scale_correction, config.where("pipeline", "scale_correction"));
		scale_->configure(config, setup.snapshot_every);
	}

	std::optional<Eigen::Isometry3d> process(const Frame& frame, FrameTable& table) override
	{
		auto t0 = SteadyClock::now();
		vo_->process(frame, table);
		table.set("ms_vo", lapMs(t0), 2);
		const MonocularState state = vo_->monocular();
		const auto rescale = [this](double factor, bool whole_map) { return vo_->rescale(factor, whole_map); };
		const ScaleApplied applied = scale_->process(prev_ ? &*prev_ : nullptr, frame, state, rescale, table);
		if (!path_) path_.emplace(frame.rig.vehicle_T_camera);
		const auto motion = path_->update(frame.t, state, applied);
		prev_ = frame;
		prev_->image = frame.image.makeDeepCopy();  // the reader may reuse the image buffer
		return motion;
	}

	Trajectory trajectory() const override { return path_ ? path_->trajectory() : Trajectory{}; }
	std::string label() const override { return "scale-corrected VO"; }
	void writeSnapshots(const std::string& dir) const override { scale_->writeSnapshots(dir); }
	std::vector<std::pair<std::string, double>> figures() const override { return scale_->figures(); }

   private:
	std::unique_ptr<MonocularVisualOdometry> vo_;
	std::unique_ptr<ScaleCorrectionModule> scale_;
	std::optional<MetricVoPath> path_;
	std::optional<Frame> prev_;
};
VLO_REGISTER_MODULE(MotionSource, "metric_mono", MetricMonoVo);
}  // namespace
}  // namespace vlo
