#include <vlo/core/error.h>
#include <vlo/viz/png.h>
#include <vlo/viz/projected_scan.h>

#include "canvas.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vlo
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

/// White strip below the image: depth colour bar on the left; on the right the counts (first row)
/// and the overlay legend (second row).
void panel(cv::Mat& out, int top, double maxDepth, const ImageOverlay& overlay, const std::string& title,
	const std::string& detail)
{
	const cv::Rect bar(16, top + 12, std::min(320, out.cols / 3), 14);
	int left = bar.x;
	if (bar.width >= 60)
	{
		const std::string label = "LiDAR depth [m]";
		canvas::colorBar(out, bar, 0, maxDepth, label, turbo);
		left = bar.x + bar.width + 12 + canvas::textSize(label, canvas::kMedium).width + 30;
	}
	// Title and detail beside the colour bar; a long title first drops the detail, then shrinks.
	const int room = out.cols - 16 - left;
	const auto fits = [&](const std::string& s, double size) { return canvas::textSize(s, size).width <= room; };
	const std::string both = title.empty() ? detail : detail.empty() ? title : title + "   " + detail;
	const std::string info = fits(both, canvas::kMedium) || title.empty() ? both : title;
	const double size = fits(info, canvas::kMedium) ? canvas::kMedium : canvas::kSmall;
	canvas::text(out, info, {out.cols - 16, top + 19}, size, canvas::kInk, canvas::HAlign::Right, canvas::VAlign::Middle);
	// Every legend item: at the normal size right of the colour bar, else smaller, else in a row of its own
	// below the bar's ticks; only an image too narrow for that drops items (better missing than overlapping).
	const auto widthsAt = [&](double size) {
		std::vector<int> w;
		for (const auto& item : overlay.legend) w.push_back(26 + canvas::textSize(item.first, size).width + 18);
		return w;
	};
	double legendSize = canvas::kMedium;
	std::vector<int> widths = widthsAt(legendSize);
	const auto total = [&] { return std::accumulate(widths.begin(), widths.end(), 0); };
	if (out.cols - 16 - total() < left) widths = widthsAt(legendSize = canvas::kSmall);
	int y = top + 46, x0 = left;
	if (out.cols - 16 - total() < left) y = top + 54, x0 = 16;
	while (!widths.empty() && out.cols - 16 - total() < x0) widths.pop_back();
	int x = out.cols - 16 - total() + 18;
	for (size_t k = 0; k < widths.size(); ++k)
	{
		const auto& [name, c] = overlay.legend[k];
		// On a grey tile like the image, so that white or black markers show too.
		cv::rectangle(out, cv::Rect(x - 2, y - 9, 19, 19), cv::Scalar(128, 128, 128), cv::FILLED);
		cv::circle(out, {x + 7, y}, 6, canvas::bgr(c), 2, cv::LINE_AA);
		canvas::text(out, name, {x + 24, y}, legendSize, canvas::kInk, canvas::HAlign::Left, canvas::VAlign::Middle);
		x += widths[k];
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
		failInput("projected scan", "image is " + std::to_string(img.cols) + "x" + std::to_string(img.rows) +
				" but the camera intrinsics are for " + std::to_string(rig.camera.width) + "x" +
				std::to_string(rig.camera.height));
	cv::Mat out(img.rows + kProjectedScanPanel, img.cols, CV_8UC3, canvas::kWhite);
	cv::Mat top = out(cv::Rect(0, 0, img.cols, img.rows));
	img.copyTo(top);

	auto pts = style.show_scan ? projectScan(scan, rig, style.min_depth) : std::vector<ProjectedPoint>{};
	std::vector<double> depths;
	for (const auto& p : pts) depths.push_back(p.depth);
	const double maxDepth = style.max_depth > 0 ? style.max_depth : autoMaxDepth(depths);
	// Far first, so that near points (which occlude far ones in reality) end up on top.
	std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.depth > b.depth; });
	const int radius = style.point_radius > 0 ? style.point_radius : pts.size() > 8000 ? 1 : 2;
	for (const auto& p : pts)
		cv::circle(top, canvas::round(p.px), radius, canvas::bgr(turbo(p.depth / maxDepth)), cv::FILLED, cv::LINE_8);
	for (const auto& s : overlay.segments)
		cv::line(top, canvas::round(s.from), canvas::round(s.to), canvas::bgr(s.color), s.thickness, cv::LINE_AA);
	for (const auto& p : overlay.points)
		cv::circle(top, canvas::round(p.px), p.radius, canvas::bgr(p.color), p.filled ? cv::FILLED : p.thickness,
			cv::LINE_AA);

	const std::string detail = style.show_scan ? std::to_string(pts.size()) + " of " + std::to_string(scan.size()) +
			" LiDAR points in view" : "";
	panel(out, img.rows, maxDepth, overlay, style.title, detail);
	return out;
}

void renderProjectedScan(const mrpt::img::CImage& image, const PointCloud& scan, const SensorRig& rig,
	const std::string& png, const ImageOverlay& overlay, const ProjectedScanStyle& style)
{
	writePng(png, drawProjectedScan(image, scan, rig, overlay, style));
}
}  // namespace vlo
