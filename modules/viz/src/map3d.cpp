#include <vlo/core/error.h>
#include <vlo/viz/map3d.h>
#include <vlo/viz/png.h>

#include "canvas.h"
#include "gl_render.h"
#include "map3d_view.h"
#include "path_height.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vlo::viz
{
namespace
{
constexpr int kPanel = 64;  // colour bar strip at the bottom

/// Turbo without its darkest tenth: the road, the lowest and densest part of a map, stays blue, not black.
Rgb heightColor(double t) { return turbo(0.1 + 0.9 * std::clamp(t, 0.0, 1.0)); }

double percentile(std::vector<double> v, double q)
{
	if (v.empty()) return 0;
	const size_t k = std::min(v.size() - 1, size_t(q * (v.size() - 1)));
	std::nth_element(v.begin(), v.begin() + k, v.end());
	return v[k];
}

/// Points that decide the framing: a sample of the map inside its 1..99 % box, plus every pose.
std::vector<Eigen::Vector3d> framingPoints(const PointCloud& map, const std::vector<const Trajectory*>& trajs)
{
	std::vector<Eigen::Vector3d> out;
	const size_t stride = std::max<size_t>(1, map.size() / 20000);
	std::vector<double> xs, ys, zs;
	for (size_t i = 0; i < map.size(); i += stride)
		xs.push_back(map[i].x), ys.push_back(map[i].y), zs.push_back(map[i].z);
	const Eigen::Vector3d lo(percentile(xs, 0.01), percentile(ys, 0.01), percentile(zs, 0.01));
	const Eigen::Vector3d hi(percentile(xs, 0.99), percentile(ys, 0.99), percentile(zs, 0.99));
	for (size_t i = 0; i < xs.size(); ++i)
	{
		const Eigen::Vector3d p(xs[i], ys[i], zs[i]);
		if ((p.array() >= lo.array()).all() && (p.array() <= hi.array()).all()) out.push_back(p);
	}
	for (const auto* t : trajs)
		for (const auto& p : *t) out.push_back(p.pose.translation());
	return out;
}

/// The path's pixels (poses in front of the camera), drawn with a white halo; markers come later.
std::vector<cv::Point2d> drawPath(cv::Mat& img, const ViewCamera& cam, const Trajectory& t, Rgb c, int width)
{
	std::vector<cv::Point2d> px;
	for (const auto& p : t)
		if (auto q = cam.project(p.pose.translation())) px.push_back(*q);
	if (px.empty()) return px;
	canvas::polyline(img, px, canvas::kWhite, width + 2);  // halo: readable over any point colour
	canvas::polyline(img, px, canvas::bgr(c), width);
	return px;
}

cv::Rect contentRect(const Map3DStyle& style)
{
	const int top = style.title.empty() ? 10 : 50;
	return {20, top, style.width - 40, style.height - top - kPanel - 10};
}
}  // namespace

ViewCamera map3DView(const PointCloud& map, const std::vector<NamedTrajectory>& trajs, const Trajectory* gt,
	const Map3DStyle& style)
{
	std::vector<const Trajectory*> all;
	if (gt) all.push_back(gt);
	for (const auto& t : trajs) all.push_back(&t.traj);
	const auto frame = framingPoints(map, all);
	if (frame.empty()) failInput("3D map view", "nothing to draw (empty map and trajectories)");
	const double az = std::isfinite(style.azimuth_deg) ? style.azimuth_deg * M_PI / 180 : acrossAzimuth(frame);
	return fitView(frame, az, style.elevation_deg * M_PI / 180, style.fov_deg * M_PI / 180, contentRect(style),
		style.width, style.height);
}

cv::Mat drawMap3D(const PointCloud& map, const std::vector<NamedTrajectory>& trajs, const Trajectory* gt,
	const Map3DStyle& style)
{
	const ViewCamera cam = map3DView(map, trajs, gt, style);
	const cv::Rect content = contentRect(style);

	PointCloud shown;
	const size_t cap = std::max<size_t>(1, style.max_points);
	const size_t step = std::max<size_t>(1, (map.size() + cap - 1) / cap);
	for (size_t i = 0; i < map.size(); i += step)
		if (std::isfinite(map[i].x) && std::isfinite(map[i].y) && std::isfinite(map[i].z)) shown.push_back(map[i]);
	// Colour by height above the path the map was built along (the first estimate), if any.
	const Trajectory* path = !trajs.empty() && !trajs[0].traj.empty() ? &trajs[0].traj : gt;
	const std::vector<float> h = heightAbovePath(shown, path ? *path : Trajectory{});
	std::vector<double> hs;
	for (size_t i = 0; i < h.size(); i += std::max<size_t>(1, h.size() / 20000)) hs.push_back(h[i]);
	double h0 = percentile(hs, 0.02), h1 = percentile(hs, 0.98);
	if (h1 - h0 < 1) h0 -= 0.5, h1 += 0.5;
	GlPoints pts;
	pts.reserve(shown.size());
	for (size_t i = 0; i < shown.size(); ++i)
		pts.push_back({Eigen::Vector3f(shown[i].x, shown[i].y, shown[i].z), heightColor((h[i] - h0) / (h1 - h0))});
	cv::Mat img = renderPoints(pts, cam, style.point_size);

	std::vector<cv::Point2d> drawn;  // pixels with content, to keep the legend off them
	for (size_t i = 0; i < pts.size(); i += std::max<size_t>(1, pts.size() / 20000))
		if (auto q = cam.project(pts[i].p.cast<double>())) drawn.push_back(*q);
	// As in the top-down view: the first trajectory is the main result, drawn last, above the others; the legend
	// keeps the list order; one start ring for the drive, a diamond where a path began later.
	std::vector<std::pair<std::vector<cv::Point2d>, Rgb>> paths;
	std::vector<canvas::LegendItem> items;
	if (gt)
	{
		paths.push_back({drawPath(img, cam, *gt, kGroundTruthColor, style.line_width + 2), kGroundTruthColor});
		items.push_back({canvas::LegendItem::Line, style.gt_name, kGroundTruthColor, style.line_width + 2});
	}
	std::vector<std::pair<std::vector<cv::Point2d>, Rgb>> estimates(trajs.size());
	for (size_t i = trajs.size(); i-- > 0;)
	{
		const Rgb c = trajs[i].color.value_or(paletteColor(i));
		estimates[i] = {drawPath(img, cam, trajs[i].traj, c, style.line_width), c};
	}
	for (size_t i = 0; i < trajs.size(); ++i)
		items.push_back({canvas::LegendItem::Line, trajs[i].name, estimates[i].second, style.line_width});
	paths.insert(paths.end(), estimates.begin(), estimates.end());
	for (const auto& p : paths) drawn.insert(drawn.end(), p.first.begin(), p.first.end());
	const bool late = canvas::startEndMarkers(img, paths, gt ? 1 : 0);  // the main result's end above the others
	items.push_back({canvas::LegendItem::Ring, "start of the drive", Rgb{40, 40, 40}});
	if (late) items.push_back({canvas::LegendItem::Diamond, "start of a path that began later", Rgb{200, 200, 200}});
	items.push_back({canvas::LegendItem::Square, "end", Rgb{200, 200, 200}});
	canvas::legend(img, canvas::emptiestCorner(content, canvas::legendSize(items), drawn), items);

	cv::rectangle(img, cv::Rect(0, style.height - kPanel, style.width, kPanel), canvas::kWhite, cv::FILLED);
	const cv::Rect bar(24, style.height - kPanel + 12, std::min(400, style.width / 3), 14);
	const std::string label = path ? "height above the path [m]" : "height z [m]";
	canvas::colorBar(img, bar, h0, h1, label + "   (" + std::to_string(map.size()) + " map points)", heightColor);
	if (!style.title.empty())
		canvas::text(img, style.title, {style.width / 2, 14}, canvas::kLarge, canvas::kInk, canvas::HAlign::Center,
			canvas::VAlign::Top, 2);
	return img;
}

void renderMap3D(const PointCloud& map, const std::vector<NamedTrajectory>& trajs, const Trajectory* gt,
	const std::string& png, const Map3DStyle& style)
{
	writePng(png, drawMap3D(map, trajs, gt, style));
}
}  // namespace vlo::viz
