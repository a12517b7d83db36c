// The ORB-SLAM2-style monocular VO of modules/vo as the visual odometry module "orb". Camera poses
// become vehicle poses through the rig's vehicle_T_camera.
#include <vlo/core/error.h>
#include <vlo/kernel/visual_odometry.h>
#include <vlo/vo/visual_odometry.h>

namespace vlo
{
namespace
{
class OrbVoModule : public MonocularVisualOdometry
{
   public:
	void configure(RunConfig& config) override
	{
		for (const auto& [section, options] : opt_.parts()) config.load(*options, section);
	}

	VisualOdometryStep process(const Frame& frame, FrameTable& table) override
	{
		const std::string where = "frame " + std::to_string(frame.index);
		if (!frame.has_image) failInput(where, "the visual odometry needs an image in every frame");
		if (!vo_)
		{
			if (!frame.rig.has_camera || !frame.rig.camera.valid())
				failInput(where, "no valid camera intrinsics in the rawlog for the visual odometry");
			vo_ = std::make_unique<vo::VisualOdometry>(frame.rig.camera, opt_);
			vo_->useMappingThread(threads_ >= 2);
			vehicle_T_camera_ = frame.rig.vehicle_T_camera;
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

		// A camera motion C seen from the vehicle: V = Tvc * C * Tvc^-1. The lever arm of Tvc is in
		// metres: in a map of unknown scale it is left out (camera path in vehicle axes), or it would
		// bend the path by (I - R) t_vc against motions in map units.
		Eigen::Isometry3d Tvc = vehicle_T_camera_;
		if (!info.metric) Tvc.translation().setZero();
		const auto toVehicle = [&](const Eigen::Isometry3d& C) { return Tvc * C * Tvc.inverse(); };
		VisualOdometryStep step;
		step.tracked = info.pose.has_value();
		if (info.pose) step.pose = toVehicle(*info.pose);
		if (info.motion) step.motion = toVehicle(*info.motion);
		mono_ = {info.motion, info.map_pose, info.new_map};
		return step;
	}

	void useThreads(int threads) override { threads_ = threads; }

	MonocularState monocular() const override { return mono_; }

	bool rescale(double factor, bool whole_map) override
	{
		if (!vo_) return false;
		return whole_map ? vo_->setMapScale(factor) : vo_->rescaleAboutWindow(factor);
	}

   private:
	vo::VoOptions opt_;
	std::unique_ptr<vo::VisualOdometry> vo_;
	Eigen::Isometry3d vehicle_T_camera_ = Eigen::Isometry3d::Identity();
	MonocularState mono_;
	int threads_ = 1;
};
VLO_REGISTER_MODULE(VisualOdometryModule, "orb", OrbVoModule);
}  // namespace
}  // namespace vlo
