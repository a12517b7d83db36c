#pragma once
// Module family "scale correction": keeps a monocular VO's map metric. Per frame it estimates the
// scale of the VO's motion C(i-1) -> C(i) and decides whether to correct the map; the correction
// itself is the caller's `rescale` (the metric VO owns both modules, the corrector knows no VO).
// Created by name ([pipeline] scale_correction) through registry<ScaleCorrectionModule>().
#include <vlo/core/frame.h>
#include <vlo/kernel/frame_table.h>
#include <vlo/kernel/registry.h>
#include <vlo/kernel/run_config.h>
#include <vlo/kernel/visual_odometry.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace vlo
{
/// What the scale corrector did to the VO map at one frame.
struct ScaleApplied
{
	double factor = 1.0;  ///< lengths measured before the correction times this are metric
	bool initial = false;  ///< the first scale of a fresh map, else a drift correction
};

class ScaleCorrectionModule
{
   public:
	/// Multiplies the VO map's lengths by `factor` (about its origin when `whole_map`, else about the
	/// local window); false when the VO had nothing to scale.
	using Rescale = std::function<bool(double factor, bool whole_map)>;

	virtual ~ScaleCorrectionModule() = default;
	/// Loads and validates the options; `snapshot_every` > 0 keeps every N-th frame for a snapshot.
	virtual void configure(RunConfig& config, int snapshot_every) = 0;
	/// `prev` is the previous frame (nullptr at the first), `vo` the VO's state at `cur`. Calls
	/// `rescale` when the map's scale is to change and returns what was applied.
	virtual ScaleApplied process(
		const Frame* prev, const Frame& cur, const MonocularState& vo, const Rescale& rescale, FrameTable& table) = 0;
	/// Draws the kept snapshots into `dir`.
	virtual void writeSnapshots(const std::string& /*dir*/) const {}
	/// Counts for summary.json.
	virtual std::vector<std::pair<std::string, double>> figures() const { return {}; }
};
}  // namespace vlo
