#pragma once
// The scale over a run (vlo-run's snapshots/scale.png): on top each frame's estimate (valid or rejected), the
// corrections applied to the VO map and their cumulative product; below, each estimate's RANSAC inlier count. Library vlo::scale_overlay.
#include <vlo/viz/series.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace vlo::scale
{
/// One row per frame that reached the scale corrector; NaN where a value does not exist.
struct ScaleHistory
{
	std::vector<double> frame;  ///< frame index
	std::vector<double> estimate;  ///< valid estimate of a metric map (NaN: none, or the initial one)
	std::vector<double> rejected;  ///< an estimate computed but not valid, e.g. too few inliers (NaN: none)
	std::vector<double> inliers;  ///< RANSAC inliers of the estimate (0 when it stopped earlier)
	std::vector<double> correction;  ///< factor applied to the metric map at this frame (NaN: none)
	std::vector<double> cumulative;  ///< product of the corrections so far (NaN: no metric map yet)

	/// Appends one frame. `correction` 1 means none; a negative `cumulative` means no metric map.
	void add(std::size_t frame_index, double estimate_or_nan, int inlier_count, double correction, double cumulative,
		double rejected_or_nan = std::nan(""));
	bool empty() const { return frame.empty(); }
};

/// The two panels of scale.png (colours: Okabe-Ito, see doc/SNAPSHOTS.md).
std::vector<viz::SeriesPanel> scalePlotPanels(const ScaleHistory& h);
/// Writes scale.png when the history holds at least one estimate or correction; returns whether it did.
bool renderScalePlot(const ScaleHistory& h, const std::string& png);
}  // namespace vlo::scale
