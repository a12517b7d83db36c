#include <vlo/scale/overlay.h>

#include <array>

namespace vlo::scale
{
namespace
{
// Legend order: what matters most first (an image too narrow for the legend drops its last items).
constexpr std::array<Stage, 6> kLegendOrder = {
	Stage::None, Stage::Ransac, Stage::Epipolar, Stage::Gradient, Stage::Triangulation, Stage::Tracking};
}  // namespace

viz::Rgb stageColor(Stage s)
{
	switch (s)
	{
		case Stage::None: return {0, 158, 115};  // bluish green
		case Stage::Ransac: return {0, 114, 178};  // blue: unlike the vermillion of the epipolar check
		case Stage::Epipolar: return {213, 94, 0};  // vermillion
		case Stage::Gradient: return {204, 121, 167};  // reddish purple
		case Stage::Triangulation: return {240, 228, 66};  // yellow
		case Stage::Tracking: return {255, 255, 255};  // white: no track to judge
	}
	return {0, 0, 0};
}

const char* stageLabel(Stage s)
{
	switch (s)
	{
		case Stage::None: return "inlier";
		case Stage::Ransac: return "RANSAC outlier";
		case Stage::Epipolar: return "off epipolar line";
		case Stage::Gradient: return "weak gradient";
		case Stage::Triangulation: return "not triangulated";
		case Stage::Tracking: return "track lost";
	}
	return "?";
}

viz::ImageOverlay scaleOverlay(const ScaleEstimate& e, bool tracks)
{
	viz::ImageOverlay o;
	std::array<int, kLegendOrder.size()> count{};
	// Inliers last, so that they are drawn on top.
	for (auto it = kLegendOrder.rbegin(); it != kLegendOrder.rend(); ++it)
		for (const auto& k : e.keypoints)
		{
			if (k.rejected_by != *it) continue;
			const viz::Rgb c = stageColor(k.rejected_by);
			if (tracks && k.rejected_by != Stage::Tracking) o.segments.push_back({k.prev, k.cur, c, 1});
			o.points.push_back({k.prev, c, 4, false, 2});
			++count[static_cast<size_t>(kLegendOrder.rend() - it - 1)];
		}
	// Stopped before RANSAC (too few survivors at some stage): the survivors are not inliers.
	const bool ransacRan = e.counts.inliers > 0;
	for (size_t i = 0; i < kLegendOrder.size(); ++i)
	{
		if (count[i] == 0) continue;
		const char* label = kLegendOrder[i] == Stage::None && !ransacRan ? "kept" : stageLabel(kLegendOrder[i]);
		o.legend.push_back({std::string(label) + " " + std::to_string(count[i]), stageColor(kLegendOrder[i])});
	}
	return o;
}
}  // namespace vlo::scale
