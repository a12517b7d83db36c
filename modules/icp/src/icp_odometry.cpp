#include <vlo/core/se3.h>
#include <vlo/core/stopwatch.h>
#include <vlo/core/sweep_times.h>
#include <vlo/icp/icp_odometry.h>
#include <vlo/icp/preprocessing.h>

#include <cmath>

namespace vlo::icp
{
namespace
{
const IcpOptions& validated(const IcpOptions& o)
{
	o.validate();
	return o;
}
}  // namespace

IcpOdometry::IcpOdometry(const IcpOptions& options)
	: opt_(validated(options)),
	  map_(opt_.voxel_size, opt_.max_points_per_voxel, opt_.map_radius),
	  threshold_(opt_.initial_threshold, opt_.min_motion, opt_.max_range)
{
}

Eigen::Isometry3d IcpOdometry::predict(const std::optional<Eigen::Isometry3d>& guess, IcpResult& r) const
{
	const bool plausible = guess && guess->translation().norm() <= opt_.max_guess_translation &&
		rotationAngle(guess->linear()) <= opt_.max_guess_rotation_deg * M_PI / 180.0;
	r.prediction = plausible ? "external" : "constant_velocity";
	return plausible ? *guess : velocity_;
}

IcpResult IcpOdometry::process(double t, const PointCloud& scan, const std::optional<Eigen::Isometry3d>& guess)
{
	IcpResult r;
	r.t = t;
	r.n_input = scan.size();
	auto clock = SteadyClock::now();
	const Eigen::Isometry3d motion = started_ ? predict(guess, r) : Eigen::Isometry3d::Identity();
	const Eigen::Isometry3d predicted = pose_ * motion;
	r.deskewed = started_ && hasTimeSpread(scan);
	// KISS-ICP keeps the scan at half the voxel size for the map and registers a coarser subset.
	const Points frame = voxelDownsample(
		cropRange(deskewExact(scan, motion, t - last_t_), opt_.min_range, opt_.max_range), 0.5 * opt_.voxel_size);
	const Points source = voxelDownsample(frame, 1.5 * opt_.voxel_size);
	r.n_valid = frame.size();
	r.n_source = source.size();
	r.ms.add("features", lapMs(clock));

	r.sigma = threshold_.sigma();
	r.pose = predicted;
	if (source.empty())
		r.reason = "no point within [" + std::to_string(opt_.min_range) + ", " + std::to_string(opt_.max_range) + "] m";
	else if (!started_ || map_.empty())
		r.status = LidarFrameStatus::Initialized;
	else
	{
		RegistrationParams params;
		params.max_distance = 3.0 * r.sigma;
		// The paper's Geman-McClure rho(e) = (e^2 / 2) / (kappa + e^2) with kappa = sigma / 3 compares kappa
		// with a squared distance: in terms of a length scale k (gemanMcClureWeight), k^2 = sigma / 3.
		params.kernel = std::sqrt(r.sigma / 3.0);
		params.max_iterations = opt_.max_iterations;
		params.convergence = opt_.convergence;
		r.registration = alignToMap(source, map_, predicted, params);
		if (r.registration.correspondences < params.min_correspondences)
			r.reason = "only " + std::to_string(r.registration.correspondences) + " correspondences within " +
				std::to_string(params.max_distance) + " m";
		else
		{
			r.status = LidarFrameStatus::Ok;
			r.pose = r.registration.pose;
		}
	}
	r.ms.add("mapping", lapMs(clock));

	if (r.status != LidarFrameStatus::Skipped)
	{
		const Eigen::Isometry3d deviation = predicted.inverse() * r.pose;
		r.model_error = threshold_.modelError(deviation);
		if (r.status == LidarFrameStatus::Ok) threshold_.addDeviation(deviation);
		map_.update(frame, r.pose);
	}
	r.motion = pose_.inverse() * r.pose;
	if (started_) velocity_ = r.motion;
	pose_ = r.pose;
	last_t_ = t;
	started_ = started_ || r.status != LidarFrameStatus::Skipped;
	r.map_points = map_.pointCount();
	r.ms.add("mapping", lapMs(clock));
	return r;
}
}  // namespace vlo::icp
