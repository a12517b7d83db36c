#include <vlo/viz/color.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace vlo::viz
{
Rgb paletteColor(std::size_t i)
{
	// Okabe-Ito without black and yellow (yellow is unreadable on white).
	static constexpr std::array<Rgb, 7> kPalette{{{0, 114, 178}, {213, 94, 0}, {0, 158, 115}, {204, 121, 167},
		{230, 159, 0}, {86, 180, 233}, {120, 60, 20}}};
	return kPalette[i % kPalette.size()];
}

Rgb turbo(double t)
{
	// Polynomial approximation of Turbo (Anton Mikhailov, Google, Apache-2.0), max error < 1/255.
	t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
	const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
	const double r = 0.13572138 + 4.61539260 * t - 42.66032258 * t2 + 132.13108234 * t3 - 152.94239396 * t4 +
		59.28637943 * t5;
	const double g = 0.09140261 + 2.19418839 * t + 4.84296658 * t2 - 14.18503333 * t3 + 4.27729857 * t4 +
		2.82956604 * t5;
	const double b = 0.10667330 + 12.64194608 * t - 60.58204836 * t2 + 110.36276771 * t3 - 89.90310912 * t4 +
		27.34824973 * t5;
	auto u8 = [](double v) { return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0))); };
	return {u8(r), u8(g), u8(b)};
}
}  // namespace vlo::viz
