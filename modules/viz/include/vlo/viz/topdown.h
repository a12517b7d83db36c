#pragma once
// Top-down (bird's-eye) view of trajectories in the vehicle frame of frame 0: x (forward at the
// start) to the right, y (left at the start) up, equal aspect, metres.
#include <vlo/io/trajectory.h>
#include <vlo/viz/color.h>
#include <vlo/viz/plot.h>

#include <opencv2/core/mat.hpp>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace vlo::viz
{
struct NamedTrajectory
{
	std::string name;
	Trajectory traj;
	std::optional<Rgb> color;  ///< default: paletteColor(index in the list)
};

struct TopDownStyle
{
	int width = 1200, height = 1000;
	std::string title;  ///< above the plot when not empty
	std::string gt_name = "ground truth";
	int line_width = 2;  ///< estimates; ground truth is drawn wider underneath
	bool show_lengths = true;  ///< path length after each legend name
	std::string unit = "m";  ///< of the coordinates, on the axes, lengths and scale bar (e.g. "map units")
	/// One value per pose of the first trajectory (e.g. its absolute error), or none. When given, that path is
	/// coloured by them (turbo, from 0 to their largest) and a colour bar labelled value_label replaces the scale bar.
	std::vector<double> values;
	std::string value_label = "value";
	/// Segments drawn thin across the paths, e.g. loop closures between two visits of a place.
	std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> links;
	std::string links_label = "loop closure";
	Rgb links_color{220, 0, 160};
};

/// The world -> pixel mapping drawTopDown uses. Throws InputError when there is no pose at all.
PlotArea topDownArea(const std::vector<NamedTrajectory>& trajs, const Trajectory* gt, const TopDownStyle& style = {});
/// BGR image of style.width x style.height. gt may be null.
cv::Mat drawTopDown(const std::vector<NamedTrajectory>& trajs, const Trajectory* gt, const TopDownStyle& style = {});
void renderTopDown(const std::vector<NamedTrajectory>& trajs, const Trajectory* gt, const std::string& png,
	const TopDownStyle& style = {});
}  // namespace vlo::viz
