#pragma once
// One camera image with the LiDAR scan projected into it, coloured by depth, plus optional overlays
// (keypoints, tracks) in caller-chosen colours, and a legend panel below the image.
#include <vlo/core/frame.h>
#include <vlo/viz/color.h>

#include <opencv2/core/mat.hpp>

#include <string>
#include <utility>
#include <vector>

namespace vlo::viz
{
struct OverlayPoint
{
	cv::Point2d px;  ///< image pixel (x right, y down)
	Rgb color;
	int radius = 4;
	bool filled = false;  ///< rings keep the image beneath visible
	int thickness = 2;  ///< of a ring
};

struct OverlaySegment
{
	cv::Point2d from, to;  ///< e.g. a track from its position in C(i-1) to C(i)
	Rgb color;
	int thickness = 1;
};

/// Drawn above the LiDAR points, segments first.
struct ImageOverlay
{
	std::vector<OverlayPoint> points;
	std::vector<OverlaySegment> segments;
	std::vector<std::pair<std::string, Rgb>> legend;  ///< e.g. {"rejected: epipolar", red}
};

struct ProjectedScanStyle
{
	double min_depth = 1.0;  ///< metres along the optical axis; nearer points are not drawn
	double max_depth = 0;  ///< colour scale end; 0: automatic (95th percentile, rounded up)
	int point_radius = 0;  ///< 0: automatic (1 px for dense scans, 2 px for sparse ones)
	bool show_scan = true;
	std::string title;  ///< e.g. "frame 120"; shown in the legend panel
};

/// Height in pixels of the legend panel that drawProjectedScan adds below the image, unless the overlay's legend
/// does not fit beside the colour bar: then it is in rows of its own below it, 24 pixels each, and the panel is taller.
constexpr int kProjectedScanPanel = 64;

struct ProjectedPoint
{
	cv::Point2d px;
	double depth = 0;  ///< z in the camera optical frame, metres
};
/// Scan points (LiDAR frame) in front of the camera that land inside the image.
std::vector<ProjectedPoint> projectScan(const PointCloud& scan, const SensorRig& rig, double min_depth = 1.0);

/// BGR image: the camera image (rows 0..H-1, same pixel coordinates) above a legend panel.
/// Throws InputError when the rig has no valid camera or the image size disagrees with it.
cv::Mat drawProjectedScan(const mrpt::img::CImage& image, const PointCloud& scan, const SensorRig& rig,
	const ImageOverlay& overlay = {}, const ProjectedScanStyle& style = {});
void renderProjectedScan(const mrpt::img::CImage& image, const PointCloud& scan, const SensorRig& rig,
	const std::string& png, const ImageOverlay& overlay = {}, const ProjectedScanStyle& style = {});
}  // namespace vlo::viz
