// New map points from a keyframe and its covisible neighbours (ORB-SLAM's CreateNewMapPoints).
#include <vlo/vo/local_mapper.h>
#include <vlo/vo/triangulation.h>

namespace vlo::vo
{
int LocalMapper::createPoints(KeyFrame* kf)
{
	const Vec3 O1 = kf->centre();
	const double median1 = kf->medianDepth();
	if (median1 <= 0) return 0;
	const double ratio_factor = opt_.scale_consistency * pyr_.factor;
	int created = 0;
	for (KeyFrame* kf2 : kf->bestCovisibles(opt_.triangulation_neighbours))
	{
		const Vec3 O2 = kf2->centre();
		const double median2 = kf2->medianDepth();
		// Too short a baseline for the scene's depth gives points with no depth information.
		if (median2 <= 0 || (O2 - O1).norm() / median2 < opt_.min_baseline_ratio) continue;
		const auto pairs = searchForTriangulation(*kf, *kf2, opt_.min_depth_ratio * median1, opt_.epipolar_chi2, ctx_);
		for (const auto& [i1, i2] : pairs)
		{
			const cv::KeyPoint& k1 = kf->key(i1);
			const cv::KeyPoint& k2 = kf2->key(i2);
			const Vec2 x1(k1.pt.x, k1.pt.y), x2(k2.pt.x, k2.pt.y);
			const Vec3 m1 = unproject(cam_, x1), m2 = unproject(cam_, x2);
			const Vec3 r1 = kf->Tcw.linear().transpose() * m1, r2 = kf2->Tcw.linear().transpose() * m2;
			const double cos_rays = r1.dot(r2) / (r1.norm() * r2.norm());
			if (cos_rays <= 0 || cos_rays >= opt_.max_parallax_cos) continue;
			Vec3 X;
			if (!triangulate(kf->Tcw, kf2->Tcw, m1, m2, X)) continue;
			const Vec3 X1 = kf->Tcw * X, X2 = kf2->Tcw * X;
			if (X1.z() <= 0 || X2.z() <= 0) continue;
			const auto l1 = static_cast<std::size_t>(k1.octave), l2 = static_cast<std::size_t>(k2.octave);
			constexpr double chi2 = 5.991;
			if ((project(cam_, X1) - x1).squaredNorm() > chi2 * pyr_.sigma2[l1]) continue;
			if ((project(cam_, X2) - x2).squaredNorm() > chi2 * pyr_.sigma2[l2]) continue;
			// The distances to both cameras must agree with the pyramid levels the point was found at.
			const double d1 = (X - O1).norm(), d2 = (X - O2).norm();
			if (d1 <= 0 || d2 <= 0) continue;
			const double ratio_dist = d2 / d1, ratio_octave = pyr_.scale[l1] / pyr_.scale[l2];
			if (ratio_dist * ratio_factor < ratio_octave || ratio_dist > ratio_octave * ratio_factor) continue;

			recent_.push_back(map_.addPointSeenBy(X, kf, kf, i1, kf2, i2, pyr_));
			++created;
		}
	}
	return created;
}
}  // namespace vlo::vo
