#include <vlo/loam/lidar_odometry.h>

#include <vlo/core/se3.h>
#include <vlo/core/se3_twist.h>
#include <vlo/core/stopwatch.h>
#include <vlo/loam/cold_start.h>
#include <vlo/loam/deskew.h>

#include <Eigen/Eigenvalues>

namespace vlo::loam
{
LidarOdometry::LidarOdometry(const LoamOptions& o)
	: opt_((o.validate(), o)),
	  features_(o),
	  odometry_(o.odometry, features_.model()),
	  mapper_(o.mapping),
	  prior_(makeMotionPrior(o.prior))
{
}

void LidarOdometry::reset()
{
	odometry_.clearReference();
	mapper_.clear();
	prior_->reset();
	frames_ = 0;
	pose_ = odom_pose_ = odom_ref_ = map_T_odom_ = Eigen::Isometry3d::Identity();
	t_prev_.reset();
	first_raw_.reset();
}

void LidarOdometry::restartFromFirst(const FeatureSet& first)
{
	if (opt_.mapping.enabled)
	{
		mapper_.clear();
		mapper_.insert(first, pose_);
	}
	if (opt_.odometry.enabled) odometry_.setReference(first);
}

std::vector<Eigen::Vector3f> LidarOdometry::mapPoints() const
{
	std::vector<Eigen::Vector3f> pts;
	mapper_.edgeMap().appendPoints(pts);
	mapper_.planeMap().appendPoints(pts);
	return pts;
}

// Unusable input: the pose follows the prior and the reference scan and map stay as they were.
LidarOdometryResult LidarOdometry::skip(LidarOdometryResult r, const std::string& why)
{
	r.status = LidarFrameStatus::Skipped;
	r.reason = why;
	r.motion = frames_ ? r.guess : Eigen::Isometry3d::Identity();
	r.pose = pose_ * r.motion;
	odom_pose_ = odom_pose_ * r.motion;
	map_T_odom_ = r.pose * odom_pose_.inverse();
	prior_->update(r.t, r.motion);
	pose_ = r.pose;
	t_prev_ = r.t;
	++frames_;
	return r;
}

void LidarOdometry::checkExternalGuess(const FeatureSet& f, const Eigen::Isometry3d& cv, LidarOdometryResult& r) const
{
	const PriorOptions& o = opt_.prior;
	const Eigen::Isometry3d d = cv.inverse() * r.guess;
	if (o.check_deviation <= 0 || !opt_.mapping.enabled || mapper_.empty() ||
		(d.translation().norm() < o.check_deviation && rotationAngle(d.linear()) * 180.0 / M_PI < o.check_deviation_deg))
		return;
	const ScanToMap::Input in = mapper_.prepare(f);
	r.guess_fit_external = mapper_.planeFit(in, pose_ * r.guess);
	r.guess_fit_constant_velocity = mapper_.planeFit(in, pose_ * cv);
	if (r.guess_fit_constant_velocity > (1.0 + o.check_margin) * r.guess_fit_external)
	{
		r.guess = cv;
		r.prior_source = "constant_velocity (external fits the map worse)";
	}
}

ScanToMap::Result LidarOdometry::alignWithPrior(
	const ScanToMap::Input& in, const Eigen::Isometry3d& guess, const PosePrior& prior, LidarOdometryResult& r) const
{
	ScanToMap::Result with = mapper_.align(in, guess, &prior);
	// In squared loss scales: the matches' own measure of a large residual, whatever weight the prior has.
	const double a = opt_.mapping.solver.loss_scale;
	r.motion_prior_cost = with.prior_geometry_cost / (a * a);
	if (with.ok && r.motion_prior_cost <= opt_.prior.max_geometry_cost)
	{
		r.motion_prior = "used";
		return with;
	}
	r.motion_prior = "dropped";
	return mapper_.align(in, guess);
}

// Scan-to-scan then scan-to-map for features f; sets the status and the odometry/map poses.
void LidarOdometry::registerFrame(
	const FeatureSet& f, const PosePrior* prior, LidarOdometryResult& r, Eigen::Isometry3d& odom, Eigen::Isometry3d& pose)
{
	auto t0 = SteadyClock::now();
	// Scan-to-scan, against the last usable scan (frames in between were skipped); not when an
	// external motion goes straight to scan-to-map.
	odom = odom_pose_ * r.guess;
	const bool external = r.prior_source == "external";
	const std::string& stage = opt_.prior.external_stage;
	r.external_stage = external ? (stage == "mapping" ? "mapping" : "odometry") : "";
	if (opt_.odometry.enabled && odometry_.hasReference() && r.external_stage != "mapping")
	{
		r.odometry = odometry_.match(f, odom_ref_.inverse() * odom);
		// auto: along a direction scan-to-scan hardly constrains (a corridor's axis) its result is
		// whatever its nearest-neighbour matches drag it to; the external motion goes to
		// scan-to-map unchanged then.
		const bool degenerate = r.odometry.ok &&
			weakTranslation(r.odometry.degeneracy, opt_.prior.min_translation_information, opt_.prior.min_weakest_ratio);
		if (external && stage == "auto" && degenerate) r.external_stage = "mapping";
		else odom = odom_ref_ * r.odometry.T_prev_curr;
	}
	r.ms.add("odometry", lapMs(t0));

	// Scan-to-map from the odometry pose carried into the map frame.
	pose = map_T_odom_ * odom;
	const bool first = (!opt_.mapping.enabled || mapper_.empty()) && (!opt_.odometry.enabled || !odometry_.hasReference());
	r.status = first ? LidarFrameStatus::Initialized : LidarFrameStatus::Ok;
	r.reason.clear();
	if (!first && opt_.mapping.enabled)
	{
		r.mapping = prior ? alignWithPrior(mapper_.prepare(f), pose, *prior, r) : mapper_.align(mapper_.prepare(f), pose);
		if (r.mapping.ok) pose = r.mapping.T_map_curr;
		else r.status = LidarFrameStatus::Degraded, r.reason = r.mapping.reason;
	}
	else if (!first && opt_.odometry.enabled && !r.odometry.ok)
		r.status = LidarFrameStatus::Degraded, r.reason = r.odometry.reason;
	r.ms.add("mapping", lapMs(t0));
}

LidarOdometryResult LidarOdometry::process(double t, const PointCloud& scan, const std::optional<Eigen::Isometry3d>& prior_motion,
	const ExternalMotionQuality& quality)
{
	return process(t, features_.extract(scan), prior_motion, quality);
}

LidarOdometryResult LidarOdometry::process(double t, ScanFeatures&& scan, const std::optional<Eigen::Isometry3d>& prior_motion,
	const ExternalMotionQuality& quality)
{
	LidarOdometryResult r;
	r.t = t;
	auto t0 = SteadyClock::now();
	r.guess = frames_ ? prior_->predict(t, prior_motion) : Eigen::Isometry3d::Identity();
	r.prior_source = frames_ ? prior_->lastSource() : "none";

	r.n_input = scan.n_input;
	r.n_valid = scan.n_valid;
	r.n_rings = scan.n_rings;
	r.ms.add("features", scan.ms + lapMs(t0));
	if (scan.n_valid == 0)
		return skip(r,
			"no usable points (" + std::to_string(scan.n_input) + " given: " +
				std::to_string(scan.n_invalid) + " invalid, " + std::to_string(scan.n_out_of_range) +
				" out of range, " + std::to_string(scan.n_out_of_fov) +
				" out of the vertical field of view)");
	if (r.n_rings < opt_.features.min_rings)
		return skip(r, "only " + std::to_string(r.n_rings) + " populated rings (min_rings " + std::to_string(opt_.features.min_rings) + ")");

	FeatureSet raw = std::move(scan.features);
	r.n_sharp = raw.sharp.size();
	r.n_less_sharp = raw.less_sharp.size();
	r.n_flat = raw.flat.size();
	r.n_less_flat = raw.less_flat.size();
	if (static_cast<int>(raw.sharp.size()) < opt_.features.min_sharp || static_cast<int>(raw.flat.size()) < opt_.features.min_flat)
		return skip(r, "too few features (" + std::to_string(raw.sharp.size()) + " sharp, " + std::to_string(raw.flat.size()) + " flat)");

	// Without deskewing, one registration. With it, the sweep is undistorted by the guessed motion,
	// registered, and undistorted again by the motion found while that changes it noticeably (at
	// the start, when the guess knows nothing, and when the motion changes). The map and the next
	// scan get the features undistorted by the final motion. Only a scan with point times (the
	// sensor's, or from the azimuth: [lidar] point_times) is deskewed.
	const bool deskewable = scan.times_from_data;
	const bool undistort = deskewable && frames_ && t_prev_ && t > *t_prev_;
	const auto deskewed = [&](const FeatureSet& src, const Eigen::Isometry3d& motion) {
		FeatureSet d = src;
		for (ScanPoints* s : {&d.sharp, &d.less_sharp, &d.flat, &d.less_flat}) deskewTabulated(*s, motion, t - *t_prev_);
		r.ms.add("odometry", lapMs(t0));
		return d;
	};
	// The first sweep had no motion to be deskewed with: the second brings one (constant velocity),
	// so in each of its passes the map and the reference restart from the first sweep deskewed.
	const bool redo_first = undistort && first_raw_ && frames_ == 1;
	// An accepted external motion also weighs in scan-to-map, as a prior, even where the check below
	// starts the registration from constant velocity: the map fit that decides the start prefers
	// LOAM's own motion where LOAM is biased (a VLP-16 among foliage under-measures every step).
	std::optional<PosePrior> motion_prior;
	if (r.prior_source == "external" && opt_.prior.motion_sigma > 0)
	{
		motion_prior = externalMotionPrior(pose_, r.guess, quality, opt_.prior, opt_.mapping.solver.loss_scale);
		r.motion_prior_information =
			Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(motion_prior->information.bottomRightCorner<3, 3>()).eigenvalues()(0);
	}
	if (const auto cv = prior_->setAside())
	{
		checkExternalGuess(raw, *cv, r);
		r.ms.add("mapping", lapMs(t0));  // lookups in the map
	}
	if (frames_ == 1 && r.prior_source != "external" && opt_.odometry.enabled && odometry_.hasReference() &&
		opt_.odometry.cold_start_range > 0)
	{
		r.guess = searchFirstMotion(odometry_, raw, opt_.odometry.cold_start_range, opt_.odometry.cold_start_step).motion;
		r.prior_source = "cold_start";
		r.ms.add("odometry", lapMs(t0));
	}
	Eigen::Isometry3d motion = r.guess, pose, odom;
	FeatureSet f = undistort ? deskewed(raw, motion) : std::move(raw);
	for (r.passes = 1;; ++r.passes)
	{
		if (redo_first) restartFromFirst(deskewed(*first_raw_, motion));
		registerFrame(f, motion_prior ? &*motion_prior : nullptr, r, odom, pose);
		if (!undistort) break;
		const Eigen::Isometry3d found = pose_.inverse() * pose;
		const Eigen::Isometry3d change = motion.inverse() * found;
		motion = found;
		t0 = SteadyClock::now();
		f = deskewed(raw, motion);
		if (r.passes >= opt_.scan.max_deskew_passes ||
			(change.translation().norm() < opt_.scan.deskew_tolerance &&
				rotationAngle(change.linear()) * 180.0 / M_PI < opt_.scan.deskew_tolerance_deg))
			break;
	}
	t0 = SteadyClock::now();
	if (opt_.mapping.enabled)
	{
		r.map_carved = mapper_.carve(f, pose);
		mapper_.insert(f, pose, r.mapping.arrived);
	}
	r.map_edge_points = mapper_.edgeMap().numPoints();
	r.map_plane_points = mapper_.planeMap().numPoints();
	r.ms.add("mapping", lapMs(t0));

	map_T_odom_ = pose * odom.inverse();
	odom_pose_ = odom_ref_ = odom;
	t0 = SteadyClock::now();
	if (opt_.odometry.enabled) odometry_.setReference(f);  // builds the search index: odometry time
	r.ms.add("odometry", lapMs(t0));
	r.motion = frames_ ? pose_.inverse() * pose : Eigen::Isometry3d::Identity();
	r.pose = pose;
	prior_->update(t, r.motion);
	pose_ = pose;
	t_prev_ = t;
	if (frames_ == 0 && deskewable) first_raw_ = f;  // f is raw: the first frame is not deskewed
	else first_raw_.reset();
	++frames_;
	return r;
}
}  // namespace vlo::loam
