#include <vlo/eval/kitti_curves.h>

#include <cmath>

namespace vlo::eval
{
namespace
{
/// The devkit plots a point only when at least 3 segments support it.
constexpr std::size_t kMinSegments = 3;

template <class Near>
void addPoint(std::vector<KittiCurvePoint>& curve, double x, const KittiResult& r, Near near)
{
	KittiCurvePoint p;
	p.x = x;
	for (const auto& seg : r.segments)
		if (near(seg))
		{
			p.t_err += seg.t_err;
			p.r_err += seg.r_err;
			++p.n;
		}
	if (p.n < kMinSegments) return;
	p.t_err /= double(p.n);
	p.r_err /= double(p.n);
	curve.push_back(p);
}
}  // namespace

KittiCurves kittiCurves(const KittiResult& r, const KittiOptions& opts)
{
	KittiCurves c;
	for (const double len : opts.lengths)
		addPoint(c.by_length, len, r, [&](const KittiSegment& s) { return std::abs(s.length - len) < 1.0; });
	for (double speed = 2; speed < 25; speed += 2)
		addPoint(c.by_speed, speed, r, [&](const KittiSegment& s) { return std::abs(s.speed - speed) < 2.0; });
	return c;
}
}  // namespace vlo::eval
