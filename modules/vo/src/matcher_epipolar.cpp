// Matching between two keyframes along epipolar segments, for the triangulation of new points.
#include <vlo/vo/matcher.h>
#include <vlo/vo/segment_grid.h>

#include <cmath>


namespace vlo::vo
{
std::vector<std::pair<int, int>> searchForTriangulation(
	const KeyFrame& k1, const KeyFrame& k2, double min_depth, double epipolar_chi2, const MatchContext& ctx)
{
	const SE3 T21 = k2.Tcw * k1.Tcw.inverse();
	const Mat3 F12 = fundamentalBetween(k1.Tcw, k2.Tcw, ctx.cam);
	const Vec3 c1_in_2 = T21.translation();  // camera 1's centre seen from camera 2
	const Vec2 epipole = c1_in_2.z() > 1e-9 ? project(ctx.cam, c1_in_2) : Vec2(-1e9, -1e9);

	// Free keypoints of k2, with what the band test needs, in one compact array.
	struct Cand
	{
		double x, y, tol2;  // tolerance: chi2 * sigma^2 of the keypoint's level
		int idx;
	};
	std::vector<Cand> free2;
	SegmentGrid grid(ctx.cam.width, ctx.cam.height, 16.0);
	double max_tol2 = 0;
	for (std::size_t j = 0; j < k2.points.size(); ++j)
	{
		if (k2.points[j]) continue;
		const cv::KeyPoint& kp = k2.feat->keys[j];
		const double sc = ctx.pyr.scale[static_cast<std::size_t>(kp.octave)];
		// Near the epipole depth is unobservable (ORB-SLAM's 10 px x scale guard).
		if ((Vec2(kp.pt.x, kp.pt.y) - epipole).squaredNorm() < 100 * sc) continue;
		grid.add(kp.pt.x, kp.pt.y, static_cast<int>(free2.size()));
		free2.push_back({kp.pt.x, kp.pt.y, epipolar_chi2 * sc * sc, static_cast<int>(j)});
		max_tol2 = std::max(max_tol2, free2.back().tol2);
	}
	const double band = std::sqrt(max_tol2);

	const std::size_t n2 = k2.points.size();
	std::vector<int> best_from(n2, -1), best_dist(n2, 256);
	std::vector<int> matched12(k1.points.size(), -1);
	for (std::size_t i = 0; i < k1.points.size(); ++i)
	{
		if (k1.points[i]) continue;
		const cv::KeyPoint& kp1 = k1.feat->keys[i];
		const Vec3 m1 = unproject(ctx.cam, Vec2(kp1.pt.x, kp1.pt.y));
		// Points nearer than min_depth (in camera 1) or behind camera 2 are not searched: the ray's
		// near end must lie in front of camera 2.
		const Vec3 near2 = T21 * (min_depth * m1);
		const Vec3 dir2 = T21.linear() * m1;
		if (near2.z() <= 0 && dir2.z() <= 0) continue;
		const Vec3 l = F12.transpose() * Vec2(kp1.pt.x, kp1.pt.y).homogeneous();
		const double ln2 = l.x() * l.x() + l.y() * l.y();
		if (ln2 <= 0) continue;
		// Along the line, keep to the segment between the projections of the near end and infinity.
		const Vec2 a = near2.z() > 0 ? project(ctx.cam, near2) : Vec2(epipole);
		const Vec2 b = dir2.z() > 0 ? project(ctx.cam, dir2) : Vec2(epipole);
		const Vec2 ab = b - a;
		const double ab2 = ab.squaredNorm();
		int best = 256, best_idx = -1;
		const uint8_t* d1 = k1.feat->descriptor(i);
		const auto consider = [&](int n) {
			const Cand& c = free2[static_cast<std::size_t>(n)];
			const double e = l.x() * c.x + l.y() * c.y + l.z();
			if (e * e > c.tol2 * ln2) return;
			if (ab2 > 1.0)
			{
				const double u = ((c.x - a.x()) * ab.x() + (c.y - a.y()) * ab.y()) / ab2;
				if (u < -0.05 || u > 1.05) return;
			}
			const int d = hamming(d1, k2.feat->descriptor(static_cast<std::size_t>(c.idx)));
			// Ties go to the lower index: the result does not depend on the grid's visiting order.
			if (d <= ctx.opt.descriptor_low && (d < best || (d == best && c.idx < best_idx))) best = d, best_idx = c.idx;
		};
		// The tests above are exact; the grid only skips keypoints far from the segment (from the whole
		// line when the segment is degenerate).
		if (ab2 > 1.0) grid.forEachNear(a - 0.05 * ab, a + 1.05 * ab, band, consider);
		else
		{
			const Vec2 foot = -l.z() * Vec2(l.x(), l.y()) / ln2, along = Vec2(-l.y(), l.x()) / std::sqrt(ln2);
			const double reach = foot.norm() + ctx.cam.width + ctx.cam.height;
			grid.forEachNear(foot - reach * along, foot + reach * along, band, consider);
		}
		if (best_idx < 0) continue;
		const auto j = static_cast<std::size_t>(best_idx);
		if (best >= best_dist[j]) continue;  // keypoint of k2 already taken by a better match
		if (best_from[j] >= 0) matched12[static_cast<std::size_t>(best_from[j])] = -1;
		best_from[j] = static_cast<int>(i);
		best_dist[j] = best;
		matched12[i] = best_idx;
	}
	RotationHistogram hist;
	for (std::size_t i = 0; i < matched12.size(); ++i)
		if (matched12[i] >= 0 && ctx.opt.check_orientation)
			hist.add(k1.feat->keys[i].angle, k2.feat->keys[static_cast<std::size_t>(matched12[i])].angle, static_cast<int>(i));
	if (ctx.opt.check_orientation)
		for (int i : hist.rejected()) matched12[static_cast<std::size_t>(i)] = -1;
	std::vector<std::pair<int, int>> out;
	for (std::size_t i = 0; i < matched12.size(); ++i)
		if (matched12[i] >= 0) out.emplace_back(static_cast<int>(i), matched12[i]);
	return out;
}
}  // namespace vlo::vo
