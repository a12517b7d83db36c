// The A-LOAM reimplementation of modules/loam as the LiDAR odometry module "aloam".
#include <vlo/kernel/lidar_odometry.h>
#include <vlo/loam/lidar_odometry.h>
#include <vlo/loam/ring_count.h>
#include <vlo/loam/rings.h>

#include <utility>

namespace vlo::loam
{
namespace
{
/// The scan's rings and features, extracted ahead of its turn.
struct PreparedLoamScan : kernel::PreparedScan
{
	explicit PreparedLoamScan(loam::ScanFeatures f) : features(std::move(f)) {}
	loam::ScanFeatures features;
};

/// Scan-to-map's J^T J (over [rotation; translation] of the LiDAR in the map, the rotation about the
/// LiDAR in the map's axes: delta's parts swapped) as the information of the LiDAR's motion since the
/// previous frame, the map and the previous pose held fixed.
Matrix6d lidarMotionInformation(const loam::LidarOdometryResult& r)
{
	Matrix6d JtJ;
	JtJ << r.mapping.JtJ.bottomRightCorner<3, 3>(), r.mapping.JtJ.bottomLeftCorner<3, 3>(),
		r.mapping.JtJ.topRightCorner<3, 3>(), r.mapping.JtJ.topLeftCorner<3, 3>();
	const auto pairs = static_cast<std::size_t>(r.mapping.n_edges + r.mapping.n_planes);
	return relativeInformation(registrationInformation(JtJ, pairs, r.mapping.rms), r.pose * r.motion.inverse());
}

class AloamModule : public kernel::LidarOdometryModule
{
   public:
	void configure(kernel::RunConfig& config) override
	{
		// In a run the caller decides whether LOAM gets a guess ([pipeline] bootstrapping); with none,
		// the external prior is constant velocity, as in A-LOAM. constant_velocity ignores any guess.
		opt_.prior.source = "external";
		for (const auto& [section, options] : opt_.parts()) config.load(*options, section);
		lo_ = std::make_unique<loam::LidarOdometry>(opt_);  // validates the options
		ahead_.emplace(opt_);
		ring_check_.emplace(config.origin(), opt_.scan, loam::RingModel(opt_.scan).elevationsDeg());
	}

	// The scan's rings and features (its own extractor: prepare and process may run on two threads).
	std::unique_ptr<kernel::PreparedScan> prepare(const Frame& frame) override
	{
		return std::make_unique<PreparedLoamScan>(ahead_->extract(frame.scan));
	}

	kernel::LidarOdometryStep process(const Frame& frame, std::unique_ptr<kernel::PreparedScan> prepared,
		const std::optional<kernel::MotionGuess>& guess, kernel::FrameTable& table) override
	{
		mount_.observe(frame);
		ring_check_->observe(frame.scan);
		const auto motion = mount_.lidarMotion(guess);
		auto* ahead = dynamic_cast<PreparedLoamScan*>(prepared.get());
		loam::ExternalMotionQuality quality;
		if (guess) quality = {guess->quality.tracked, guess->quality.length_error};
		const auto r = ahead ? lo_->process(frame.t, std::move(ahead->features), motion, quality)
							 : lo_->process(frame.t, frame.scan, motion, quality);

		table.set("lo_status", std::string(toString(r.status)));
		table.set("lo_prior", r.prior_source);
		table.set("lo_guess_stage", r.external_stage);
		table.set("lo_guess_fit_external", r.guess_fit_external, 1);
		table.set("lo_guess_fit_cv", r.guess_fit_constant_velocity, 1);
		table.set("lo_points", static_cast<long long>(r.n_valid));
		table.set("lo_sharp", static_cast<long long>(r.n_sharp));
		table.set("lo_flat", static_cast<long long>(r.n_flat));
		table.set("lo_odom_iterations", static_cast<long long>(r.odometry.iterations));
		table.set("lo_odom_rms_m", r.odometry.rms, 4);
		table.set("lo_map_rounds", static_cast<long long>(r.mapping.rounds));
		table.set("lo_map_iterations", static_cast<long long>(r.mapping.iterations));
		table.set("lo_map_rms_m", r.mapping.rms, 4);
		table.set("lo_map_min_eigen", r.mapping.degeneracy.min_eigenvalue, 2);
		table.set("lo_degenerate", r.mapping.degeneracy.degenerate);
		table.set("lo_map_matches", static_cast<long long>(r.mapping.n_edges + r.mapping.n_planes));
		table.set("lo_map_points", static_cast<long long>(r.map_edge_points + r.map_plane_points));
		table.setTimes("lo_", r.ms);
		table.set("lo_reason", r.reason);
		// external_stage = auto decides from these (doc/LOAM.md)
		table.set("lo_odom_info_min", r.odometry.degeneracy.translation_information(0), 1);
		table.set("lo_odom_info_next", r.odometry.degeneracy.translation_information(1), 1);
		// ... and edges = auto and the rounds of scan-to-map from this
		table.set("lo_map_plane_info", r.mapping.plane_information, 1);
		table.set("lo_map_rough", r.mapping.used_rough_planes);
		if (!r.motion_prior.empty()) setMotionPriorColumns(r, table);
		kernel::LidarOdometryStep step{mount_.vehiclePose(r.pose), std::nullopt};
		if (r.status == LidarFrameStatus::Ok && r.mapping.ok)
			step.information = mount_.vehicleInformation(lidarMotionInformation(r), r.motion);
		return step;
	}

   private:
	/// Only where an external motion weighed in scan-to-map: a run without one (mode lo) has no such columns.
	static void setMotionPriorColumns(const loam::LidarOdometryResult& r, kernel::FrameTable& table)
	{
		table.set("lo_motion_prior", r.motion_prior);
		table.set("lo_motion_prior_info", r.motion_prior_information, 1);
		table.set("lo_motion_prior_cost", r.motion_prior_cost, 2);
		// ... against the map's own information along its weakest direction (the same units)
		table.set("lo_map_info_min", r.mapping.degeneracy.translation_information(0), 1);
	}

	loam::LoamOptions opt_;
	std::unique_ptr<loam::LidarOdometry> lo_;
	std::optional<loam::ScanFeatureExtractor> ahead_;
	std::optional<loam::RingModelCheck> ring_check_;
	kernel::LidarMount mount_;
};
VLO_REGISTER_MODULE(kernel::LidarOdometryModule, "aloam", AloamModule);
}  // namespace
}  // namespace vlo::loam
