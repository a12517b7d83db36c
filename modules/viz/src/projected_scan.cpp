#include <vlo/core/error.h>
#include <vlo/viz/png.h>
#include <vlo/viz/projected_scan.h>

#include "canvas.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vlo::viz
{
namespace
{
cv::Mat toBgr(const mrpt::img::CImage& image)
{
	const cv::Mat& m = image.asCvMatRef();
	cv::Mat out;
	if (m.channels() == 1)
		cv::cvtColor(m, out, cv::COLOR_GRAY2BGR);
	else if (m.channels() == 3)
		out = m.clone();
	else
		failInput("projected scan", "image has " + std::to_string(m.channels()) + " channels, expected 1 or 3");
	if (out.depth() != CV_8U) failInput("projected scan", "image is not 8-bit");
	return out;
}

double autoMaxDepth(std::vector<double> depths)
{
	if (depths.empty()) return 10.0;
	const size_t k = depths.size() * 95 / 100;
	std::nth_element(depths.begin(), depths.begin() + k, depths.end());
	const double step = niceStep(depths[k] / 4);
	return std::max(step, std::ceil(depths[k] / step) * step);
}

constexpr int kPanelPad = 16, kTile = 19;

/// The depth colour bar at the left of the panel (none in an image too narrow for it).
cv::Rect depthBar(int cols, int top) { return {kPanelPad, top + 12, std::min(320, cols / 3), 14}; }
const std::string kDepthLabel = "LiDAR depth [m]";
/// Left end of the room right of the colour bar and its label.
int besideBar(int cols)
{
	const cv::Rect bar = depthBar(cols, 0);
	return bar.width >= 60 ? bar.x + bar.width + 12 + canvas::textSize(kDepthLabel, canvas::kMedium).width + 30 : bar.x;
}

/// Where the overlay legend's items go (centre of each item's tile, relative to the panel's top) and how tall the
/// panel must be for them: beside the colour bar at the normal size if they fit, else smaller, else in rows of their
/// own below the bar, as many as they need. No item is dropped.
struct LegendLayout
{
	double size = canvas::kMedium;
	std::vector<cv::Point> at;
	int panel_height = kProjectedScanPanel;
};

LegendLayout layoutLegend(const ImageOverlay& overlay, int cols)
{
	LegendLayout l;
	const auto widthsAt = [&](double size) {
		std::vector<int> w;
		for (const auto& item : overlay.legend) w.push_back(26 + canvas::textSize(item.first, size).width + 18);
		return w;
	};
	std::vector<int> widths = widthsAt(l.size);
	const auto total = [&] { return std::accumulate(widths.begin(), widths.end(), 0); };
	const int left = besideBar(cols), right = cols - kPanelPad;
	if (right - total() < left) widths = widthsAt(l.size = canvas::kSmall);
	if (right - total() >= left)  // one row beside the bar, right-aligned
	{
		for (int k = 0, x = right - total() + 18; k < int(widths.size()); x += widths[k++]) l.at.push_back({x + 7, 46});
		return l;
	}
	int x = kPanelPad, y = 62;  // below the bar's tick labels
	for (int w : widths)
	{
		if (x > kPanelPad && x + w - 18 > right) x = kPanelPad, y += 24;
		l.at.push_back({x + 7, y});
		x += w;
	}
	l.panel_height = std::max(kProjectedScanPanel, y + 16);
	return l;
}

/// White strip below the image: depth colour bar on the left; on the right the title and counts (first row)
/// and the overlay legend (second row, or rows of its own).
void panel(cv::Mat& out, int top, double maxDepth, const ImageOverlay& overlay, const LegendLayout& layout,
	const std::string& title, const std::string& detail)
{
	const cv::Rect bar = depthBar(out.cols, top);
	if (bar.width >= 60) canvas::colorBar(out, bar, 0, maxDepth, kDepthLabel, turbo);
	// Title and detail beside the colour bar; a long title first drops the detail, then shrinks.
	const int room = out.cols - kPanelPad - besideBar(out.cols);
	const auto fits = [&](const std::string& s, double size) { return canvas::textSize(s, size).width <= room; };
	const std::string both = title.empty() ? detail : detail.empty() ? title
																	 : title + "   " + detail;
	const std::string info = fits(both, canvas::kMedium) || title.empty() ? both : title;
	const double size = fits(info, canvas::kMedium) ? canvas::kMedium : canvas::kSmall;
	canvas::text(out, info, {out.cols - kPanelPad, top + 19}, size, canvas::kInk, canvas::HAlign::Right,
		canvas::VAlign::Middle);
	for (size_t k = 0; k < layout.at.size(); ++k)
	{
		const auto& [name, c] = overlay.legend[k];
		const cv::Point at = layout.at[k] + cv::Point(0, top);
		// On a grey tile like the image, so that white or black markers show too.
		cv::rectangle(out, cv::Rect(at.x - 9, at.y - 9, kTile, kTile), cv::Scalar(128, 128, 128), cv::FILLED);
		cv::circle(out, at, 6, canvas::bgr(c), 2, cv::LINE_AA);
		canvas::text(out, name, {at.x + 17, at.y}, layout.size, canvas::kInk, canvas::HAlign::Left, canvas::VAlign::Middle);
	}
}
}  // namespace

std::vector<ProjectedPoint> projectScan(const PointCloud& scan, const SensorRig& rig, double min_depth)
{
	const PinholeCamera& cam = rig.camera;
	const Eigen::Isometry3d T = rig.camera_T_lidar();
	std::vector<ProjectedPoint> out;
	for (const auto& p : scan)
	{
		const Eigen::Vector3d q = T * Eigen::Vector3d(p.x, p.y, p.z);
		if (!(q.z() >= min_depth)) continue;  // also drops NaN
		const double u = cam.fx * q.x() / q.z() + cam.cx, v = cam.fy * q.y() / q.z() + cam.cy;
		// Pixel centres are at integer coordinates: pixel k covers [k - 0.5, k + 0.5).
		if (u < -0.5 || v < -0.5 || u >= cam.width - 0.5 || v >= cam.height - 0.5) continue;
		out.push_back({{u, v}, q.z()});
	}
	return out;
}

cv::Mat drawProjectedScan(const mrpt::img::CImage& image, const PointCloud& scan, const SensorRig& rig,
	const ImageOverlay& overlay, const ProjectedScanStyle& style)
{
	if (!rig.has_camera || !rig.camera.valid()) failInput("projected scan", "the sensor rig has no valid camera");
	const cv::Mat img = toBgr(image);
	if (img.cols != rig.camera.width || img.rows != rig.camera.height)
		failInput("projected scan",
			"image is " + std::to_string(img.cols) + "x" + std::to_string(img.rows) +
				" but the camera intrinsics are for " + std::to_string(rig.camera.width) + "x" +
				std::to_string(rig.camera.height));
	const LegendLayout layout = layoutLegend(overlay, img.cols);
	cv::Mat out(img.rows + layout.panel_height, img.cols, CV_8UC3, canvas::kWhite);
	cv::Mat top = out(cv::Rect(0, 0, img.cols, img.rows));
	img.copyTo(top);

	auto pts = style.show_scan ? projectScan(scan, rig, style.min_depth) : std::vector<ProjectedPoint>{};
	std::vector<double> depths;
	for (const auto& p : pts) depths.push_back(p.depth);
	const double maxDepth = style.max_depth > 0 ? style.max_depth : autoMaxDepth(depths);
	// Far first, so that near points (which occlude far ones in reality) end up on top.
	std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.depth > b.depth; });
	const int radius = style.point_radius > 0 ? style.point_radius : pts.size() > 8000 ? 1
																					   : 2;
	for (const auto& p : pts)
		cv::circle(top, canvas::round(p.px), radius, canvas::bgr(turbo(p.depth / maxDepth)), cv::FILLED, cv::LINE_8);
	for (const auto& s : overlay.segments)
		cv::line(top, canvas::round(s.from), canvas::round(s.to), canvas::bgr(s.color), s.thickness, cv::LINE_AA);
	for (const auto& p : overlay.points)
		cv::circle(top, canvas::round(p.px), p.radius, canvas::bgr(p.color), p.filled ? cv::FILLED : p.thickness,
			cv::LINE_AA);

	const std::string detail = style.show_scan ? std::to_string(pts.size()) + " of " + std::to_string(scan.size()) +
			" LiDAR points in view"
											   : "";
	panel(out, img.rows, maxDepth, overlay, layout, style.title, detail);
	return out;
}

void renderProjectedScan(const mrpt::img::CImage& image, const PointCloud& scan, const SensorRig& rig,
	const std::string& png, const ImageOverlay& overlay, const ProjectedScanStyle& style)
{
	writePng(png, drawProjectedScan(image, scan, rig, overlay, style));
}
}  // namespace vlo::viz
