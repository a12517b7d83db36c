// Matching by descriptor in a window: map initialisation and the reference-keyframe fall-back.
#include <vlo/vo/matcher.h>

namespace vlo::vo
{
int searchKeyFrame(const KeyFrame& kf, TrackedFrame& cur, const SE3* predicted, const MatchContext& ctx)
{
	std::vector<int> dist_of(cur.size(), 256);
	std::vector<int> from(cur.size(), -1);  // kf keypoint matched to each cur keypoint
	for (std::size_t i = 0; i < kf.points.size(); ++i)
	{
		MapPoint* mp = kf.points[i];
		if (!mp || mp->bad) continue;
		Vec2 u(kf.feat->keys[i].pt.x, kf.feat->keys[i].pt.y);
		if (predicted)
		{
			const Vec3 Xc = *predicted * mp->pos;
			if (Xc.z() <= 0) continue;
			u = project(ctx.cam, Xc);
		}
		int best = 256, second = 256, best_idx = -1;
		for (int j : cur.feat->grid.inArea(u.x(), u.y(), ctx.opt.reference_radius))
		{
			const int d = hamming(kf.feat->descriptor(i), cur.feat->descriptor(static_cast<std::size_t>(j)));
			if (d < best)
				second = best, best = d, best_idx = j;
			else if (d < second)
				second = d;
		}
		if (best_idx < 0 || best > ctx.opt.descriptor_low || best >= ctx.opt.reference_ratio * second) continue;
		const auto j = static_cast<std::size_t>(best_idx);
		if (best < dist_of[j]) dist_of[j] = best, from[j] = static_cast<int>(i);  // one match per keypoint
	}
	RotationHistogram hist;
	for (std::size_t j = 0; j < cur.size(); ++j)
		if (from[j] >= 0 && ctx.opt.check_orientation) hist.add(kf.feat->keys[static_cast<std::size_t>(from[j])].angle, cur.feat->keys[j].angle, static_cast<int>(j));
	if (ctx.opt.check_orientation)
		for (int j : hist.rejected()) from[static_cast<std::size_t>(j)] = -1;
	int n = 0;
	for (std::size_t j = 0; j < cur.size(); ++j)
		if (from[j] >= 0)
		{
			cur.points[j] = kf.points[static_cast<std::size_t>(from[j])];
			cur.outlier[j] = 0;
			++n;
		}
	return n;
}

std::vector<int> searchForInitialization(const Features& f1, const Features& f2, std::vector<Vec2>& prev,
	double radius, double ratio, int max_level, const MatchContext& ctx)
{
	std::vector<int> m12(f1.size(), -1), m21(f2.size(), -1), dist21(f2.size(), 256);
	for (std::size_t i = 0; i < f1.size(); ++i)
	{
		const int level = f1.keys[i].octave;
		if (level > max_level) continue;
		const double r = radius * ctx.pyr.scale[static_cast<std::size_t>(level)];
		int best = 256, second = 256, best_idx = -1;
		for (int j : f2.grid.inArea(prev[i].x(), prev[i].y(), r, level, level))
		{
			const int d = hamming(f1.descriptor(i), f2.descriptor(static_cast<std::size_t>(j)));
			if (d > dist21[static_cast<std::size_t>(j)]) continue;
			if (d < best)
				second = best, best = d, best_idx = j;
			else if (d < second)
				second = d;
		}
		if (best_idx < 0 || best > ctx.opt.descriptor_low || best >= ratio * second) continue;
		const auto j = static_cast<std::size_t>(best_idx);
		if (m21[j] >= 0) m12[static_cast<std::size_t>(m21[j])] = -1;  // the better match wins
		m12[i] = best_idx;
		m21[j] = static_cast<int>(i);
		dist21[j] = best;
	}
	if (ctx.opt.check_orientation)
	{
		RotationHistogram hist;
		for (std::size_t i = 0; i < f1.size(); ++i)
			if (m12[i] >= 0) hist.add(f1.keys[i].angle, f2.keys[static_cast<std::size_t>(m12[i])].angle, static_cast<int>(i));
		for (int i : hist.rejected()) m12[static_cast<std::size_t>(i)] = -1;
	}
	for (std::size_t i = 0; i < f1.size(); ++i)
		if (m12[i] >= 0)
		{
			const auto& p = f2.keys[static_cast<std::size_t>(m12[i])].pt;
			prev[i] = Vec2(p.x, p.y);
		}
	return m12;
}
}  // namespace vlo::vo
