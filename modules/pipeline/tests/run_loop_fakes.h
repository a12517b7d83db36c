#pragma once
// The fake stages test_run_loop.cpp runs the pipeline with: a monocular and a stereo VO, a scale
// corrector and LiDAR odometries (well-behaved, failing, interrupted) with known outputs, each
// registered under a name of its own, recording in `seen` what the pipeline gave them.
#include <vlo/core/error.h>
#include <vlo/kernel/lidar_odometry.h>
#include <vlo/kernel/scale_correction.h>
#include <vlo/kernel/visual_odometry.h>

#include <Eigen/Geometry>
#include <csignal>
#include <optional>
#include <utility>
#include <vector>

namespace vlo::pipeline::fakes
{
using namespace vlo::kernel;

constexpr int kFrames = 6;
constexpr double kStep = 0.5;  ///< [m] the vehicle's true motion per frame

/// What the fakes saw, reset by each test.
struct Seen
{
	std::vector<std::optional<kernel::MotionGuess>> lidar_guesses;
	std::vector<long> scale_prev_index;  ///< index of the previous frame given to the corrector, -1 = none
	std::vector<std::pair<double, bool>> rescales;  ///< (factor, whole_map) asked of the VO
	int vo_frames = 0;
};
inline Seen seen;

inline Eigen::Isometry3d forward(double metres)  ///< along the camera's z axis
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation().z() = metres;
	return T;
}

/// A monocular VO: lost at frame 0, makes a map at frame 1 in which one frame's 0.5 m is 1 unit, then
/// tracks; rescale() multiplies its map's lengths.
class FakeMonoVo : public MonocularVisualOdometry
{
   public:
	void configure(kernel::RunConfig&) override {}
	kernel::VisualOdometryStep process(const Frame& frame, kernel::FrameTable& table) override
	{
		++seen.vo_frames;
		table.set("vo_fake", static_cast<long long>(frame.index));
		kernel::VisualOdometryStep step;
		if (frame.index == 0) return step;
		const double units = units_per_step_;
		step.new_map = frame.index == 1;
		step.tracked = 40 + int(frame.index);
		step.camera_map_pose = forward(units * double(frame.index - 1));
		if (frame.index >= 2) step.camera_motion = forward(units);
		step.camera_pose = forward(units * double(frame.index));  // not used by the metric VO
		return step;
	}
	bool rescale(double factor, bool whole_map) override
	{
		seen.rescales.push_back({factor, whole_map});
		units_per_step_ *= factor;
		return true;
	}

   private:
	double units_per_step_ = 1.0;
};
VLO_REGISTER_MODULE(kernel::VisualOdometryModule, "fake_mono", FakeMonoVo);

/// A metric VO (stereo-like): the camera's motion in metres from frame 1 on, nothing to rescale.
class FakeStereoVo : public VisualOdometryModule
{
   public:
	void configure(kernel::RunConfig&) override {}
	kernel::VisualOdometryStep process(const Frame& frame, kernel::FrameTable&) override
	{
		kernel::VisualOdometryStep step;
		step.metric = true;
		step.camera_pose = forward(kStep * double(frame.index));
		if (frame.index >= 1) step.camera_motion = forward(kStep);
		return step;
	}
};
VLO_REGISTER_MODULE(kernel::VisualOdometryModule, "fake_stereo", FakeStereoVo);

/// Metric scale 0.5 at the first estimate (frame 2), a 10 % drift correction at frame 4.
class FakeScale : public ScaleCorrectionModule
{
   public:
	void configure(kernel::RunConfig&, int) override {}
	kernel::ScaleCorrection process(const Frame* prev, const Frame& cur, const kernel::VisualOdometryStep& vo, kernel::FrameTable& table) override
	{
		seen.scale_prev_index.push_back(prev ? long(prev->index) : -1);
		table.set("scale_fake", vo.camera_motion.has_value());
		const double error = 0.01 * double(cur.index);  // the estimate's relative standard error
		if (cur.index == 2) return {kernel::ScaleCorrection::Kind::Initial, 0.5, "first", error};
		if (cur.index == 4) return {kernel::ScaleCorrection::Kind::Drift, 1.1, "drift", error};
		return {kernel::ScaleCorrection::Kind::None, 1.0, "", error};
	}
	std::vector<std::pair<std::string, double>> figures() const override { return {{"fake_figure", 42}}; }
};
VLO_REGISTER_MODULE(kernel::ScaleCorrectionModule, "fake_scale", FakeScale);

/// Follows the truth; records the guesses it is given.
class FakeLidar : public LidarOdometryModule
{
   public:
	void configure(kernel::RunConfig&) override {}
	kernel::LidarOdometryStep process(const Frame& frame, std::unique_ptr<kernel::PreparedScan> /*prepared*/,
		const std::optional<kernel::MotionGuess>& guess, kernel::FrameTable& table) override
	{
		seen.lidar_guesses.push_back(guess);
		table.set("lo_fake", static_cast<long long>(frame.scan.size()));
		return {Eigen::Isometry3d(Eigen::Translation3d(kStep * double(frame.index), 0, 0)), std::nullopt};
	}
};
VLO_REGISTER_MODULE(kernel::LidarOdometryModule, "fake_lidar", FakeLidar);

/// Fails at frame 3 (with two threads, while the motion source works on frame 4).
class FailingLidar : public FakeLidar
{
   public:
	kernel::LidarOdometryStep process(const Frame& frame, std::unique_ptr<kernel::PreparedScan> prepared,
		const std::optional<kernel::MotionGuess>& guess, kernel::FrameTable& table) override
	{
		if (frame.index == 3) failInput("lidar", "fails at frame 3");
		return FakeLidar::process(frame, std::move(prepared), guess, table);
	}
};
VLO_REGISTER_MODULE(kernel::LidarOdometryModule, "failing_lidar", FailingLidar);

/// Ctrl-C while it works on frame 3.
class InterruptedLidar : public FakeLidar
{
   public:
	kernel::LidarOdometryStep process(const Frame& frame, std::unique_ptr<kernel::PreparedScan> prepared,
		const std::optional<kernel::MotionGuess>& guess, kernel::FrameTable& table) override
	{
		if (frame.index == 3) std::raise(SIGINT);
		return FakeLidar::process(frame, std::move(prepared), guess, table);
	}
};
VLO_REGISTER_MODULE(kernel::LidarOdometryModule, "interrupted_lidar", InterruptedLidar);

/// Fails at frame 4.
class FailingMonoVo : public FakeMonoVo
{
   public:
	kernel::VisualOdometryStep process(const Frame& frame, kernel::FrameTable& table) override
	{
		if (frame.index == 4) failInput("vo", "fails at frame 4");
		return FakeMonoVo::process(frame, table);
	}
};
VLO_REGISTER_MODULE(kernel::VisualOdometryModule, "failing_mono", FailingMonoVo);
}  // namespace vlo::pipeline::fakes
