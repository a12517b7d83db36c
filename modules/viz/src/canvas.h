#pragma once
// Internal OpenCV drawing helpers shared by the 2D snapshots: text, axes, legends, colour bars.
#include <vlo/viz/color.h>
#include <vlo/viz/plot.h>

#include <opencv2/core.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace vlo::viz::canvas
{
inline cv::Scalar bgr(Rgb c) { return {double(c.b), double(c.g), double(c.r)}; }
const cv::Scalar kInk{40, 40, 40}, kGrid{228, 228, 228}, kWhite{255, 255, 255};

enum class HAlign
{
	Left,
	Center,
	Right
};
enum class VAlign
{
	Top,
	Middle,
	Bottom
};
/// Font sizes: ticks and legend text, axis labels, titles.
constexpr double kSmall = 0.5, kMedium = 0.6, kLarge = 0.8;

cv::Size textSize(const std::string& text, double scale, int thickness = 1);
void text(cv::Mat& img, const std::string& s, cv::Point at, double scale, cv::Scalar color = kInk,
	HAlign h = HAlign::Left, VAlign v = VAlign::Bottom, int thickness = 1);
/// Text rotated 90 degrees counter-clockwise, centred on `center` (for y-axis labels).
void textVertical(cv::Mat& img, const std::string& s, cv::Point center, double scale, cv::Scalar color = kInk);

/// Anti-aliased polyline with sub-pixel precision; pixel coordinates.
void polyline(cv::Mat& img, const std::vector<cv::Point2d>& pts, cv::Scalar color, int thickness);
cv::Point round(const cv::Point2d& p);

/// Number with as many decimals as `step` needs ("250", "0.5", "1.02").
std::string formatTick(double v, double step);
/// Grid, frame, ticks with labels every xstep/ystep world units, and axis labels.
void axes(cv::Mat& img, const PlotArea& a, double xstep, double ystep, const std::string& xlabel,
	const std::string& ylabel);

struct LegendItem
{
	enum Kind
	{
		Line,
		Dot,
		Square,
		Ring,
		Diamond
	} kind = Line;
	std::string label;
	Rgb color;
	int thickness = 2;
};
cv::Size legendSize(const std::vector<LegendItem>& items);
/// Boxed legend, one item per row, with a white background over whatever is below.
void legend(cv::Mat& img, cv::Point topLeft, const std::vector<LegendItem>& items);

/// A filled diamond with an ink outline, e.g. where a trajectory starts later than the drive.
void diamond(cv::Mat& img, cv::Point center, int radius, Rgb fill);

/// Start and end markers of paths given as pixels with their colours, the drive's first: the drive's start is one
/// neutral ring (every path that starts there shares it); a path that starts elsewhere (a VO that initialised later)
/// gets a diamond in its colour there. Every end is a square in its path's colour, path `on_top`'s (the main result's)
/// above the others. Returns whether a diamond was drawn.
bool startEndMarkers(
	cv::Mat& img, const std::vector<std::pair<std::vector<cv::Point2d>, Rgb>>& paths, std::size_t on_top);

/// Top-left of a box of `size` in the corner of `area` that covers the fewest `pts`, skipping `taken`
/// (an earlier box). `pad` pixels from the area's edges.
cv::Point emptiestCorner(const cv::Rect& area, cv::Size size, const std::vector<cv::Point2d>& pts,
	const cv::Rect& taken = {}, int pad = 12);

/// Tick step of a colour bar `width` pixels long from vmin to vmax: about five ticks, fewer when their labels
/// would touch (vmax > vmin).
double colorBarStep(double vmin, double vmax, int width);
/// Horizontal colour bar in `bar` from vmin to vmax with ticks below and `label` to the right.
void colorBar(cv::Mat& img, const cv::Rect& bar, double vmin, double vmax, const std::string& label,
	const std::function<Rgb(double)>& colormap);
}  // namespace vlo::viz::canvas
