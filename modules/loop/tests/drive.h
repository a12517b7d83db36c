#pragma once
// A drive through a synthetic world fed to LoopClosure: the true path, its drifting odometry, a scan
// of the world at every true pose, and what the loop closure made of it.
#include <vlo/loop/keyframe.h>
#include <vlo/loop/loop_closure.h>

#include "synthetic_places.h"

#include <chrono>
#include <functional>
#include <thread>

namespace vlo::loop::test
{
struct DriveResult
{
	Trajectory truth, odometry, corrected;
	std::vector<LoopRecord> loops;
	std::size_t keyframes = 0;

	std::size_t accepted() const
	{
		std::size_t n = 0;
		for (const auto& l : loops) n += l.accepted;
		return n;
	}
	std::size_t rejectedFor(const std::string& reason) const
	{
		std::size_t n = 0;
		for (const auto& l : loops) n += !l.accepted && l.reason.rfind(reason, 0) == 0;
		return n;
	}
};

/// A path sampled every `step` metres of arc length s in [0, length), 10 m/s.
inline Trajectory samplePath(const std::function<Eigen::Isometry3d(double)>& at, double length, double step = 1.0)
{
	Trajectory t;
	for (double s = 0; s < length; s += step) t.push_back({s / 10.0, at(s)});
	return t;
}

/// Each frame's information given to addFrame, from the frame's index and the odometry's poses.
using FrameInformation = std::function<std::optional<Matrix6d>(std::size_t frame, const Trajectory& odometry)>;

/// `pause_ms` after each frame: an odometry slower than the loop thread (0: as fast as it goes).
/// Without `information` the odometry edges get the per-metre model.
inline DriveResult drive(const World& world, const Trajectory& truth, double scale, double yaw_bias_per_metre,
	const LoopOptions& options = LoopOptions{}, unsigned seed = 11, int pause_ms = 0,
	const FrameInformation& information = {})
{
	DriveResult r;
	r.truth = truth;
	r.odometry = driftingOdometry(truth, scale, yaw_bias_per_metre);
	Eigen::Isometry3d vehicle_T_lidar = Eigen::Isometry3d::Identity();
	vehicle_T_lidar.translation() = Eigen::Vector3d(0.3, 0, 1.7);
	std::mt19937 rng(seed);
	LoopClosure loop(options);
	// Only keyframes' scans are used: the others are left empty (and not rendered, for speed).
	KeyframeSelector keyframe(options.keyframe_distance, options.keyframe_angle_deg * M_PI / 180);
	for (std::size_t i = 0; i < truth.size(); ++i)
	{
		loop.addFrame(static_cast<long long>(i), truth[i].t, r.odometry[i].pose,
			information && i > 0 ? information(i, r.odometry) : std::nullopt,
			keyframe.take(r.odometry[i].pose) ? scanFrom(world, truth[i].pose * vehicle_T_lidar, rng) : PointCloud{},
			vehicle_T_lidar);
		if (pause_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(pause_ms));
	}
	loop.finish();
	r.corrected = loop.corrected();
	r.loops = loop.loops();
	r.keyframes = loop.keyframes();
	return r;
}
}  // namespace vlo::loop::test
