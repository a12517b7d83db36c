#pragma once
// Colours shared by every snapshot: a categorical palette for trajectories (Okabe-Ito, readable by
// colour-blind reviewers), a neutral colour for ground truth, and colormaps for depth and height.
#include <cstddef>
#include <cstdint>

namespace vlo::viz
{
struct Rgb
{
	std::uint8_t r = 0, g = 0, b = 0;
	bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

/// i-th trajectory colour (cycles after 7; none of them is grey).
Rgb paletteColor(std::size_t i);
/// Ground truth: dark neutral grey, distinct from every palette colour.
constexpr Rgb kGroundTruthColor{90, 90, 90};

/// Google's Turbo colormap, t in [0, 1] (clamped): dark blue (near/low) -> red (far/high).
Rgb turbo(double t);
}  // namespace vlo::viz
