#pragma once
// Module family "motion source": whatever gives the LiDAR odometry its initial guess, the vehicle's
// motion since the previous frame, e.g. a stereo VO alone, or a monocular VO kept metric by a scale
// corrector. Created by name ([pipeline] motion_source) through registry<MotionSource>().
#include <vlo/core/frame.h>
#include <vlo/core/trajectory.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/motion_guess.h>
#include <vlo/kernel/registry.h>
#include <vlo/kernel/run_config.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vlo::kernel
{
/// The modules a motion source composes, by registry name, from [pipeline].
struct MotionSourceSetup
{
	std::string visual_odometry;  ///< registry<VisualOdometryModule>() name
	std::string scale_correction;  ///< registry<ScaleCorrectionModule>() name (monocular VO only)
	int snapshot_every = 0;  ///< keep every N-th frame's diagnostics for a snapshot (0 = none)
	int threads = 1;  ///< [pipeline] threads as a count: the composed modules may use threads of their own
};

class MotionSource
{
   public:
	virtual ~MotionSource() = default;
	/// Creates and configures the composed modules.
	virtual void configure(RunConfig& config, const MotionSourceSetup& setup) = 0;
	/// The vehicle's motion since the previous frame (pose of the current vehicle frame in the
	/// previous one) and its quality, when known; writes its diagnostics columns. The frame is shared,
	/// never changed again, so that a source may keep it for the next frame without a copy.
	virtual std::optional<MotionGuess> process(std::shared_ptr<const Frame> frame, FrameTable& table) = 0;
	/// Vehicle poses relative to the vehicle at the start, as written to trajectory_vo.tum.
	virtual Trajectory trajectory() const = 0;
	/// Name of that trajectory in plots.
	virtual std::string label() const = 0;
	virtual void writeSnapshots(const std::string& /*dir*/) const {}
	/// Counts for summary.json.
	virtual std::vector<std::pair<std::string, double>> figures() const { return {}; }
};
}  // namespace vlo::kernel
