#pragma once
// The LiDAR odometry and mapping of one sensor: preprocessing, features, scan-to-scan odometry
// and scan-to-map refinement every frame, with the initial guess from a MotionPrior.
//
//   LidarOdometry lo(options);
//   for (each scan) { auto r = lo.process(t, scan, vo_motion_or_nullopt); use r.pose; }
//   lo.mapPoints();  // for map.pcd
#include <vlo/core/frame.h>
#include <vlo/core/lidar_frame_status.h>
#include <vlo/core/stage_times.h>
#include <vlo/loam/features.h>
#include <vlo/loam/mapping.h>
#include <vlo/loam/motion_prior.h>
#include <vlo/loam/odometry.h>
#include <vlo/loam/options.h>
#include <vlo/loam/pose_prior.h>
#include <vlo/loam/rings.h>
#include <vlo/loam/scan_features.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>

namespace vlo::loam
{
struct LidarOdometryResult
{
	double t = 0;
	/// Ok: scan-to-map succeeded (scan-to-scan without mapping); Degraded: pose from the other stage
	/// or the prior; Skipped: unusable input, pose propagated by the prior.
	LidarFrameStatus status = LidarFrameStatus::Skipped;
	std::string reason;  ///< empty when Ok
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< LiDAR in the first LiDAR frame
	Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();  ///< pose of this frame in the previous
	Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();  ///< the prior's motion
	/// constant_velocity | external | none | cold_start (the first motion searched) |
	/// constant_velocity (external fits the map worse)
	std::string prior_source;
	/// When an external guess was checked against the map: each guess's fit (ScanToMap::planeFit), else 0.
	double guess_fit_external = 0, guess_fit_constant_velocity = 0;
	/// Where an external guess entered: odometry (scan-to-scan) | mapping (scan-to-map) | "" (none)
	std::string external_stage;
	/// The external motion as a residual of scan-to-map ([loam.prior] motion_sigma): "" (none) | used |
	/// dropped (it pulled against the map: max_geometry_cost)
	std::string motion_prior;
	/// Its translation information along its weakest direction, in unit-weight plane matches (the
	/// units of lo_map_plane_info), and how much it raised the matches' cost [loss_scale^2]
	double motion_prior_information = 0, motion_prior_cost = 0;

	std::size_t n_input = 0, n_valid = 0;  ///< points given / kept after preprocessing
	int n_rings = 0;  ///< populated rings
	std::size_t n_sharp = 0, n_less_sharp = 0, n_flat = 0, n_less_flat = 0;
	int passes = 0;  ///< registrations run (more than one only when deskewing)
	ScanToScanOdometry::Result odometry;  ///< iterations, matches, residual, ok/reason (last pass)
	ScanToMap::Result mapping;  ///< iterations, matches, residual, degeneracy, ok/reason
	std::size_t map_edge_points = 0, map_plane_points = 0;
	std::size_t map_carved = 0;  ///< map points removed as free space this frame
	/// features (preprocessing and extraction), odometry (deskew and scan-to-scan), mapping (scan-to-map and map update)
	StageTimes ms{{"features", "odometry", "mapping"}};
};

class LidarOdometry
{
   public:
	/// Validates the options (throws InputError naming the bad key).
	explicit LidarOdometry(const LoamOptions& o = {});

	/// Processes the scan taken at time t (LiDAR frame). `prior_motion` is the caller's guess of
	/// the motion since the previous frame (the pose of this LiDAR frame in the previous one);
	/// the ConstantVelocity prior ignores it. Never throws on bad data: see status and reason.
	/// `quality` is what the guess's source says of it, which weighs it as a prior of scan-to-map.
	LidarOdometryResult process(double t, const PointCloud& scan, const std::optional<Eigen::Isometry3d>& prior_motion,
		const ExternalMotionQuality& quality = {});
	/// The same from the scan's features computed ahead (a ScanFeatureExtractor with the same
	/// options): identical results. The features are consumed.
	LidarOdometryResult process(double t, ScanFeatures&& scan, const std::optional<Eigen::Isometry3d>& prior_motion,
		const ExternalMotionQuality& quality = {});

	void reset();
	std::size_t frames() const { return frames_; }
	const Eigen::Isometry3d& pose() const { return pose_; }
	const LoamOptions& options() const { return opt_; }
	const ScanToMap& mapper() const { return mapper_; }
	/// Every map point (edges, then planes) in the first LiDAR frame.
	std::vector<Eigen::Vector3f> mapPoints() const;

   private:
	LidarOdometryResult skip(LidarOdometryResult r, const std::string& why);
	void registerFrame(const FeatureSet& f, const PosePrior* prior, LidarOdometryResult& r, Eigen::Isometry3d& odom,
		Eigen::Isometry3d& pose);
	/// Scan-to-map from `guess` with the prior, and again without it where the prior pulls against
	/// the map (max_geometry_cost).
	ScanToMap::Result alignWithPrior(const ScanToMap::Input& in, const Eigen::Isometry3d& guess, const PosePrior& prior,
		LidarOdometryResult& r) const;
	/// An external guess far from constant velocity: LOAM starts from constant velocity instead where
	/// that fits the map better ([loam.prior] check_*).
	void checkExternalGuess(const FeatureSet& f, const Eigen::Isometry3d& cv, LidarOdometryResult& r) const;
	/// The map and the scan-to-scan reference hold only `first`, the first frame's features (deskewed).
	void restartFromFirst(const FeatureSet& first);

	LoamOptions opt_;
	ScanFeatureExtractor features_;
	ScanToScanOdometry odometry_;
	ScanToMap mapper_;
	std::unique_ptr<MotionPrior> prior_;

	std::size_t frames_ = 0;
	Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();  ///< map frame, last frame
	Eigen::Isometry3d odom_pose_ = Eigen::Isometry3d::Identity();  ///< odometry frame, last frame
	Eigen::Isometry3d odom_ref_ = Eigen::Isometry3d::Identity();  ///< odometry frame, reference scan
	Eigen::Isometry3d map_T_odom_ = Eigen::Isometry3d::Identity();  ///< A-LOAM's wmap_T_odom
	std::optional<double> t_prev_;
	std::optional<FeatureSet> first_raw_;  ///< the first frame's features, until the second deskews them
};
}  // namespace vlo::loam
