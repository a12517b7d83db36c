// The ORB-SLAM2-style monocular VO of modules/vo as the visual odometry module "orb".
#include <vlo/core/error.h>
#include <vlo/kernel/visual_odometry.h>
#include <vlo/vo/visual_odometry.h>

namespace vlo::vo
{
namespace
{
class OrbVoModule : public kernel::MonocularVisualOdometry
{
   public:
	void configure(kernel::RunConfig& config) override
	{
		for (const auto& [section, options] : opt_.parts()) config.load(*options, section);
	}

	kernel::VisualOdometryStep process(const Frame& frame, kernel::FrameTable& table) override
	{
		const std::string where = "frame " + std::to_string(frame.index);
		if (!frame.has_image) failInput(where, "the visual odometry needs an image in every frame");
		if (!vo_)
		{
			if (!frame.rig.has_camera || !frame.rig.camera.valid())
				failInput(where, "no valid camera intrinsics in the rawlog for the visual odometry");
			vo_ = std::make_unique<vo::VisualOdometry>(frame.rig.camera, opt_);
			vo_->useMappingThread(threads_ >= 2);
		}
		const vo::VoFrameInfo info = vo_->process(frame.image.asCvMatRef(), frame.t);  // grey already

		table.set("vo_state", std::string(vo::toString(info.state)));
		table.set("vo_reason", info.reason);
		table.set("vo_features", static_cast<long long>(info.features));
		table.set("vo_matches", static_cast<long long>(info.matches));
		table.set("vo_map_points", static_cast<long long>(info.map_points));
		table.set("vo_keyframes", static_cast<long long>(info.keyframes));
		table.set("vo_keyframe", info.keyframe);
		table.set("vo_reinit", static_cast<long long>(info.reinits));
		table.set("vo_metric", info.metric);
		table.setTimes("vo_", info.ms);

		kernel::VisualOdometryStep step;
		step.camera_pose = info.pose;
		step.camera_motion = info.motion;
		step.camera_map_pose = info.map_pose;
		step.new_map = info.new_map;
		step.metric = info.metric;
		step.tracked = info.matches;
		return step;
	}

	void useThreads(int threads) override { threads_ = threads; }

	bool rescale(double factor, bool whole_map) override
	{
		if (!vo_) return false;
		return whole_map ? vo_->setMapScale(factor) : vo_->rescaleAboutWindow(factor);
	}

   private:
	vo::VoOptions opt_;
	std::unique_ptr<vo::VisualOdometry> vo_;
	int threads_ = 1;
};
VLO_REGISTER_MODULE(kernel::VisualOdometryModule, "orb", OrbVoModule);
}  // namespace
}  // namespace vlo::vo
