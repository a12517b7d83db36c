#pragma once
// Module family "scale correction": keeps a monocular VO's map metric. Per frame it estimates the
// scale of the VO's motion C(i-1) -> C(i) and returns its decision, which the metric VO applies to
// the VO's map before the next frame (the corrector knows no VO).
// Created by name ([pipeline] scale_correction) through registry<ScaleCorrectionModule>().
#include <vlo/core/frame.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/registry.h>
#include <vlo/kernel/run_config.h>
#include <vlo/kernel/visual_odometry.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace vlo::kernel
{
/// A scale corrector's decision at one frame: what to do to the VO's map, or nothing, and why.
struct ScaleCorrection
{
	enum class Kind
	{
		None,  ///< leave the map as it is
		Initial,  ///< the first, metric scale of a fresh map: the whole map about its origin
		Drift  ///< a drift correction: the map about the local window's earliest keyframe
	};
	Kind kind = Kind::None;
	double factor = 1.0;  ///< lengths measured before the correction times this are metric
	std::string why;  ///< what decided it
	/// Relative standard error of this frame's scale estimate: the spread of its inliers' scales over
	/// the scale and the square root of their count; NaN without an estimate of two inliers or more.
	double relative_error = std::numeric_limits<double>::quiet_NaN();

	bool apply() const { return kind != Kind::None; }
};

class ScaleCorrectionModule
{
   public:
	virtual ~ScaleCorrectionModule() = default;
	/// Loads and validates the options; `snapshot_every` > 0 keeps every N-th frame for a snapshot.
	virtual void configure(RunConfig& config, int snapshot_every) = 0;
	/// `prev` is the previous frame (nullptr at the first), `vo` the VO's step at `cur`. A correction
	/// comes only for a frame the VO tracked in its map (`vo.camera_motion`), which it can scale; the
	/// module counts it as applied.
	virtual ScaleCorrection process(const Frame* prev, const Frame& cur, const VisualOdometryStep& vo, FrameTable& table) = 0;
	/// Draws the kept snapshots into `dir`.
	virtual void writeSnapshots(const std::string& /*dir*/) const {}
	/// Counts for summary.json.
	virtual std::vector<std::pair<std::string, double>> figures() const { return {}; }
};
}  // namespace vlo::kernel
