#include <vlo/icp/preprocessing.h>
#include <vlo/icp/registration.h>
#include <vlo/icp/voxel_map.h>
#include <vlo/loop/verification.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vlo::loop
{
namespace
{
// Coarse stage (KISS-ICP point to point): pulls in a guess that is only the descriptor's yaw, the two
// visits being up to a keyframe spacing and a lane apart. Coarse: a sparse map, few iterations.
constexpr double kCoarseVoxel = 1.0, kCoarseGate = 3.0, kCoarseKernel = 1.0, kCoarseConvergence = 1e-3;
constexpr int kCoarsePointsPerVoxel = 5, kCoarseIterations = 15;
constexpr int kIterations = 30;
// The scan is registered at three times the keyframe's voxel (as KISS-ICP registers at 1.5x its map's
// 0.5 x voxel): a third of the points for about the same constraint, and a verification that keeps up
// with the keyframes. The submap, its keyframes overlapping, is thinned to the keyframe's voxel,
// keeping the candidate's own points first (candidateSubmap's order): the square circuit's revisit
// error 0.017 m unthinned, 0.078 m thinned in keyframe order, 0.012 m thinned candidate first.
constexpr double kQueryVoxelRatio = 3.0;
// Fine stage (point to plane) gate before the last one at inlier_distance [m].
constexpr double kFineGate = 1.0;
// [m] how far a registration from the descriptor's guess may move: beyond, it would be no verification.
constexpr double kReach = 10.0;

/// The descriptor's guess: the query's viewpoint turned by the yaw at the candidate's position.
Eigen::Isometry3d descriptorGuess(const DescriptorMatch& match)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(match.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	return T * Eigen::Translation3d(0, -match.viewpoint_y, 0);
}

std::string formatted(const char* what, double value, const char* op, double limit)
{
	char text[128];
	std::snprintf(text, sizeof text, "%s %.3g %s %.3g", what, value, op, limit);
	return text;
}

Verification described(const DescriptorMatch& match, double path_between)
{
	Verification v;
	v.record.descriptor_distance = match.distance;
	v.record.yaw_deg = match.yaw * 180 / M_PI;
	v.record.path_between = path_between;
	return v;
}

std::string driftReason(double drift, double limit) { return formatted("drift too large:", drift, ">", limit); }
}  // namespace

icp::Points candidateSubmap(const std::vector<Keyframe>& keyframes, std::size_t center, int half, std::size_t end)
{
	icp::Points submap;
	const Eigen::Isometry3d center_T_world = keyframes[center].odometry.inverse();
	const auto add = [&](std::size_t k) {
		const Eigen::Isometry3d center_T_k = center_T_world * keyframes[k].odometry;
		for (const auto& p : keyframes[k].points) submap.push_back(center_T_k * p.cast<double>());
	};
	// The candidate first, then its neighbours nearest first: where the submap is thinned, the points
	// kept are those the odometry's local error displaced least.
	add(center);
	for (std::size_t d = 1; d <= static_cast<std::size_t>(half); ++d)
	{
		if (center >= d) add(center - d);
		if (center + d < end) add(center + d);
	}
	return submap;
}

double maxDrift(double path_between, const LoopOptions& options)
{
	return options.max_drift_per_metre * path_between + options.max_drift_floor;
}

std::optional<Verification> rejectOutOfReach(const DescriptorMatch& match,
	const Eigen::Isometry3d& odometry_candidate_T_current, double path_between, const LoopOptions& options)
{
	const double apart = odometry_candidate_T_current.translation().norm(), limit = maxDrift(path_between, options);
	if (apart <= limit + kReach) return std::nullopt;
	Verification v = described(match, path_between);
	v.record.drift = apart;  // from the guess: the same position
	v.record.reason = driftReason(apart, limit);
	return v;
}

Verification verifyLoop(const ScanPoints& current, const icp::Points& submap, const DescriptorMatch& match,
	const Eigen::Isometry3d& odometry_candidate_T_current, double path_between, const LoopOptions& options)
{
	Verification v = described(match, path_between);
	LoopRecord& r = v.record;
	icp::Points full;
	full.reserve(current.size());
	for (const auto& p : current) full.push_back(p.cast<double>());
	const icp::Points scan = icp::voxelDownsample(full, kQueryVoxelRatio * options.scan_voxel);
	if (scan.empty() || submap.empty())
	{
		r.reason = "empty scan";
		return v;
	}

	icp::VoxelMap coarse_map(kCoarseVoxel, kCoarsePointsPerVoxel, std::numeric_limits<double>::infinity());
	coarse_map.addPoints(submap);
	icp::RegistrationParams coarse;
	coarse.max_distance = kCoarseGate;
	coarse.kernel = kCoarseKernel;
	coarse.max_iterations = kCoarseIterations;
	coarse.convergence = kCoarseConvergence;
	const Eigen::Isometry3d coarse_pose = icp::alignToMap(scan, coarse_map, descriptorGuess(match), coarse).pose;

	const PlaneMap map(icp::voxelDownsample(submap, options.scan_voxel));
	const double inlier = options.inlier_distance;
	PlaneFit fit = alignPointToPlane(scan, map, coarse_pose, kFineGate, kFineGate / 2, kIterations);
	fit = alignPointToPlane(scan, map, fit.pose, inlier, inlier / 2, kIterations);
	r.candidate_T_current = fit.pose;

	// An inlier lies within inlier_distance of the submap's surface: of the plane of its nearest submap
	// point (within the fine gate), or of that point where there is no plane. The points of a surface
	// thinned to a voxel are up to a voxel apart: their own distances would count good points out.
	std::size_t inliers = 0;
	double sum_d2 = 0;
	std::size_t index = 0;
	double d2 = 0;
	Eigen::Vector3d n;
	for (const auto& p : scan)
	{
		const Eigen::Vector3d q = fit.pose * p;
		if (!map.nearest(q, index, d2) || d2 > kFineGate * kFineGate) continue;
		if (map.normal(index, n)) d2 = std::pow(n.dot(q - map.point(index)), 2);
		if (d2 <= inlier * inlier) ++inliers, sum_d2 += d2;
	}
	r.inlier_fraction = static_cast<double>(inliers) / static_cast<double>(scan.size());
	r.rms = inliers ? std::sqrt(sum_d2 / static_cast<double>(inliers)) : 0.0;
	r.constraint = translationConstraint(fit.information);
	r.drift = (odometry_candidate_T_current.translation() - fit.pose.translation()).norm();
	const double max_drift = maxDrift(path_between, options);

	if (r.inlier_fraction < options.min_inlier_fraction)
		r.reason = formatted("few inliers:", r.inlier_fraction, "<", options.min_inlier_fraction);
	else if (r.constraint < options.min_constraint)
		r.reason = formatted("degenerate:", r.constraint, "<", options.min_constraint);
	else if (r.drift > max_drift)
		r.reason = driftReason(r.drift, max_drift);
	else
	{
		r.accepted = true;
		// Weighed as the odometry's registrations are (registrationInformation): one loop does not
		// outweigh kilometres of odometry.
		v.information = registrationInformation(fit.information, fit.pairs, fit.rms);
	}
	return v;
}
}  // namespace vlo::loop
