#pragma once
// Oblique 3D view of a point-cloud map (coloured by height) with trajectories, rendered offscreen
// with mrpt::opengl::CFBORender (EGL, no display). Map and trajectories share the world frame
// (the vehicle frame of frame 0, z up).
#include <vlo/core/frame.h>
#include <vlo/viz/topdown.h>

#include <opencv2/core/mat.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace vlo::viz
{
struct Map3DStyle
{
	int width = 1600, height = 1000;
	std::string title;
	double azimuth_deg = NAN;  ///< where the camera stands, from +x towards +y; NAN: across the route
	double elevation_deg = 35;  ///< above the horizon
	double fov_deg = 35;  ///< vertical field of view
	float point_size = 2;  ///< pixels
	/// Evenly subsampled above this: 2-pixel points cover the 1600 x 1000 image at 400k, and rendering
	/// costs ~220 bytes a point (mrpt::opengl and Mesa's copies), so memory stays bounded for any map.
	std::size_t max_points = 500'000;
	int line_width = 3;  ///< estimates; ground truth is drawn wider underneath
	std::string gt_name = "ground truth";
};

/// BGR image of style.width x style.height. Throws InputError when there is nothing to draw.
cv::Mat drawMap3D(const PointCloud& map, const std::vector<NamedTrajectory>& trajs, const Trajectory* gt,
	const Map3DStyle& style = {});
void renderMap3D(const PointCloud& map, const std::vector<NamedTrajectory>& trajs, const Trajectory* gt,
	const std::string& png, const Map3DStyle& style = {});
}  // namespace vlo::viz
