#include <vlo/scale/elevation_offset.h>

#include <cmath>

namespace vlo::scale
{
PointCloud raiseElevations(const PointCloud& scan, double offset_deg)
{
	PointCloud out = scan;
	const double d = offset_deg * M_PI / 180;
	for (auto& p : out)
	{
		const double h = std::hypot(double(p.x), double(p.y));
		if (h < 1e-9) continue;  // straight up or down: no azimuth to keep
		const double r = std::sqrt(h * h + double(p.z) * p.z);
		const double elevation = std::atan2(double(p.z), h) + d;
		const double scale = r * std::cos(elevation) / h;
		p.x = static_cast<float>(p.x * scale);
		p.y = static_cast<float>(p.y * scale);
		p.z = static_cast<float>(r * std::sin(elevation));
	}
	return out;
}
}  // namespace vlo::scale
