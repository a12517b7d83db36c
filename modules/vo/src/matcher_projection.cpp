// Matching by projection of map points into the current frame (motion model, local map).
#include <vlo/vo/matcher.h>

namespace vlo::vo
{
namespace
{
/// A keypoint is free when it has no point yet or only one that no keyframe observes.
bool isFree(const TrackedFrame& f, int i)
{
	const MapPoint* p = f.points[static_cast<std::size_t>(i)];
	return !p || p->numObservations() == 0;
}
}  // namespace

int searchByProjection(TrackedFrame& cur, const TrackedFrame& last, double radius, const MatchContext& ctx)
{
	RotationHistogram hist;
	std::vector<int> matched;
	const SE3& Tcw = cur.Tcw;
	for (std::size_t i = 0; i < last.size(); ++i)
	{
		MapPoint* mp = last.points[i];
		if (!mp || mp->bad || last.outlier[i]) continue;
		const Vec3 Xc = Tcw * mp->pos;
		if (Xc.z() <= 0) continue;
		const Vec2 u = project(ctx.cam, Xc);
		if (!inImage(ctx.cam, u)) continue;
		const cv::KeyPoint& lk = last.feat->keys[i];
		const int level = lk.octave;
		const double r = radius * ctx.pyr.scale[static_cast<std::size_t>(level)];
		int best = 256, best_idx = -1;
		for (int j : cur.feat->grid.inArea(u.x(), u.y(), r, level - 1, level + 1))
		{
			if (!isFree(cur, j)) continue;
			const int d = hamming(mp->desc.data(), cur.feat->descriptor(static_cast<std::size_t>(j)));
			if (d < best) best = d, best_idx = j;
		}
		if (best_idx < 0 || best > ctx.opt.descriptor_high) continue;
		cur.points[static_cast<std::size_t>(best_idx)] = mp;
		cur.outlier[static_cast<std::size_t>(best_idx)] = 0;
		matched.push_back(best_idx);
		if (ctx.opt.check_orientation) hist.add(lk.angle, cur.feat->keys[static_cast<std::size_t>(best_idx)].angle, best_idx);
	}
	int n = static_cast<int>(matched.size());
	if (ctx.opt.check_orientation)
		for (int j : hist.rejected())
		{
			cur.points[static_cast<std::size_t>(j)] = nullptr;
			--n;
		}
	return n;
}

int searchLocalPoints(TrackedFrame& cur, const std::vector<MapPoint*>& local, const MatchContext& ctx)
{
	const Vec3 Ow = centre(cur.Tcw);
	int n = 0;
	for (MapPoint* mp : local)
	{
		if (mp->bad || mp->mark_seen == cur.index) continue;  // already matched in this frame
		const Vec3 Xc = cur.Tcw * mp->pos;
		if (Xc.z() <= 0) continue;
		const Vec2 u = project(ctx.cam, Xc);
		if (!inImage(ctx.cam, u)) continue;
		const Vec3 PO = mp->pos - Ow;
		const double dist = PO.norm();
		if (dist < 0.8 * mp->min_dist || dist > 1.2 * mp->max_dist) continue;
		const double view_cos = PO.dot(mp->normal) / dist;
		if (view_cos < 0.5) continue;
		++mp->visible;
		const int level = mp->predictLevel(dist, ctx.pyr);
		// Wider window for oblique views, whose appearance and position are less certain.
		const double r = ctx.opt.local_radius * (view_cos > 0.998 ? 2.5 : 4.0) * ctx.pyr.scale[static_cast<std::size_t>(level)];
		int best = 256, second = 256, best_level = -1, second_level = -1, best_idx = -1;
		for (int j : cur.feat->grid.inArea(u.x(), u.y(), r, level - 1, level))
		{
			if (!isFree(cur, j)) continue;
			const int d = hamming(mp->desc.data(), cur.feat->descriptor(static_cast<std::size_t>(j)));
			const int l = cur.feat->keys[static_cast<std::size_t>(j)].octave;
			if (d < best)
			{
				second = best, second_level = best_level;
				best = d, best_level = l, best_idx = j;
			}
			else if (d < second)
				second = d, second_level = l;
		}
		if (best_idx < 0 || best > ctx.opt.descriptor_high) continue;
		if (best_level == second_level && best > ctx.opt.local_ratio * second) continue;
		cur.points[static_cast<std::size_t>(best_idx)] = mp;
		cur.outlier[static_cast<std::size_t>(best_idx)] = 0;
		++n;
	}
	return n;
}
}  // namespace vlo::vo
