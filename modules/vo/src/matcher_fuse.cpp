// Fusion of duplicate map points by projection into a keyframe.
#include <vlo/vo/matcher.h>

namespace vlo::vo
{
int fuse(KeyFrame* kf, const std::vector<MapPoint*>& points, double radius, const MatchContext& ctx)
{
	const Vec3 Ow = kf->centre();
	int fused = 0;
	for (MapPoint* mp : points)
	{
		if (!mp || mp->bad || mp->indexIn(kf) >= 0) continue;
		const Vec3 Xc = kf->Tcw * mp->pos;
		if (Xc.z() <= 0) continue;
		const Vec2 u = project(ctx.cam, Xc);
		if (!inImage(ctx.cam, u)) continue;
		const Vec3 PO = mp->pos - Ow;
		const double dist = PO.norm();
		if (dist < mp->min_dist || dist > mp->max_dist || PO.dot(mp->normal) < 0.5 * dist) continue;
		const int level = mp->predictLevel(dist, ctx.pyr);
		const double r = radius * ctx.pyr.scale[static_cast<std::size_t>(level)];
		int best = 256, best_idx = -1;
		for (int j : kf->feat->grid.inArea(u.x(), u.y(), r, level - 1, level))
		{
			const cv::KeyPoint& kp = kf->key(j);
			const double e2 = (Vec2(kp.pt.x, kp.pt.y) - u).squaredNorm();
			if (e2 * ctx.pyr.inv_sigma2[static_cast<std::size_t>(kp.octave)] > 5.991) continue;  // 2 dof, 95%
			const int d = hamming(mp->desc.data(), kf->feat->descriptor(static_cast<std::size_t>(j)));
			if (d < best) best = d, best_idx = j;
		}
		if (best_idx < 0 || best > ctx.opt.descriptor_low) continue;
		MapPoint*& slot = kf->points[static_cast<std::size_t>(best_idx)];
		if (slot && !slot->bad)
		{
			// Keep the better observed of the two.
			if (slot->numObservations() > mp->numObservations())
				mp->replaceWith(slot);
			else
				slot->replaceWith(mp);
		}
		else
		{
			mp->addObservation(kf, best_idx);
			slot = mp;
		}
		++fused;
	}
	return fused;
}
}  // namespace vlo::vo
