// KISS-ICP's method (modules/icp) as the LiDAR odometry module "icp".
#include <vlo/icp/icp_odometry.h>
#include <vlo/kernel/lidar_odometry.h>

namespace vlo::icp
{
namespace
{
/// The last J^T J of the registration (over a left twist of the LiDAR in the map) as the information
/// of the LiDAR's motion since the previous frame, the map and the previous pose held fixed.
Matrix6d lidarMotionInformation(const IcpResult& r)
{
	const Matrix6d JtJ = informationFromLeftTwist(r.registration.JtJ, r.registration.pose.translation());
	return relativeInformation(registrationInformation(JtJ, r.registration.correspondences, r.registration.rms),
		r.pose * r.motion.inverse());
}

class IcpModule : public kernel::LidarOdometryModule
{
   public:
	void configure(kernel::RunConfig& config) override
	{
		config.load(opt_, "icp");
		odometry_ = std::make_unique<icp::IcpOdometry>(opt_);
	}

	kernel::LidarOdometryStep process(const Frame& frame, std::unique_ptr<kernel::PreparedScan> /*prepared*/,
		const std::optional<kernel::MotionGuess>& guess, kernel::FrameTable& table) override
	{
		mount_.observe(frame);
		const auto r = odometry_->process(frame.t, frame.scan, mount_.lidarMotion(guess));  // its quality unused

		table.set("lo_status", std::string(toString(r.status)));
		table.set("lo_prior", r.prediction);
		table.set("lo_points", static_cast<long long>(r.n_valid));
		table.set("lo_icp_source", static_cast<long long>(r.n_source));
		table.set("lo_icp_deskew", r.deskewed);
		table.set("lo_map_iterations", static_cast<long long>(r.registration.iterations));
		table.set("lo_map_rms_m", r.registration.rms, 4);
		table.set("lo_map_matches", static_cast<long long>(r.registration.correspondences));
		table.set("lo_icp_sigma_m", r.sigma, 4);
		table.set("lo_icp_model_error_m", r.model_error, 4);
		table.set("lo_map_points", static_cast<long long>(r.map_points));
		table.setTimes("lo_", r.ms);
		table.set("lo_reason", r.reason);
		kernel::LidarOdometryStep step{mount_.vehiclePose(r.pose), std::nullopt};
		if (r.status == LidarFrameStatus::Ok)
			step.information = mount_.vehicleInformation(lidarMotionInformation(r), r.motion);
		return step;
	}

   private:
	icp::IcpOptions opt_;
	std::unique_ptr<icp::IcpOdometry> odometry_;
	kernel::LidarMount mount_;
};
VLO_REGISTER_MODULE(kernel::LidarOdometryModule, "icp", IcpModule);
}  // namespace
}  // namespace vlo::icp
