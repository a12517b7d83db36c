#include <vlo/core/elevation_offset.h>

#include <cmath>

namespace vlo
{
void raiseElevations(PointCloud& scan, double offset_deg)
{
	// A rotation by the offset in each ray's vertical plane (horizontal distance h, height z): no
	// trigonometry per point (a 120k-point sweep costs well under a millisecond).
	const double c = std::cos(offset_deg * M_PI / 180), s = std::sin(offset_deg * M_PI / 180);
	for (auto& p : scan)
	{
		const double h = std::sqrt(double(p.x) * p.x + double(p.y) * p.y);
		if (h < 1e-9) continue;  // straight up or down: no azimuth to keep
		const double h2 = h * c - p.z * s, f = h2 / h;
		p.z = static_cast<float>(h * s + p.z * c);
		p.x = static_cast<float>(p.x * f);
		p.y = static_cast<float>(p.y * f);
	}
}
}  // namespace vlo
