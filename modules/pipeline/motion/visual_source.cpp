// Motion source "visual": the visual odometry alone, in its own units. Metric for a stereo or RGB-D
// VO; a monocular VO's map scale otherwise (mode vo, or a baseline without scale correction).
#include <vlo/core/stopwatch.h>
#include <vlo/kernel/motion_source.h>
#include <vlo/kernel/visual_odometry.h>

namespace vlo::pipeline
{
namespace
{
class VisualSource : public kernel::MotionSource
{
   public:
	void configure(kernel::RunConfig& config, const kernel::MotionSourceSetup& setup) override
	{
		vo_ = kernel::registry<kernel::VisualOdometryModule>().create(setup.visual_odometry, config.where("pipeline", "visual_odometry"));
		vo_->configure(config);
		vo_->useThreads(setup.threads);
	}

	std::optional<kernel::MotionGuess> process(std::shared_ptr<const Frame> frame, kernel::FrameTable& table) override
	{
		auto t0 = SteadyClock::now();
		const kernel::VisualOdometryStep step = vo_->process(*frame, table);
		table.set("ms_vo", lapMs(t0), 2);
		mount_.observe(*frame);
		if (step.camera_pose) path_.push_back({frame->t, mount_.vehicle(*step.camera_pose, step.metric)});
		if (!step.camera_motion) return std::nullopt;
		return kernel::MotionGuess{mount_.vehicle(*step.camera_motion, step.metric), {}};  // quality unknown
	}

	Trajectory trajectory() const override { return path_; }
	std::string label() const override { return "visual odometry"; }

   private:
	std::unique_ptr<kernel::VisualOdometryModule> vo_;
	kernel::CameraMount mount_;
	Trajectory path_;
};
VLO_REGISTER_MODULE(kernel::MotionSource, "visual", VisualSource);
}  // namespace
}  // namespace vlo::pipeline
