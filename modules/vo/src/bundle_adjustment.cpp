// Bundle adjustment of a keyframe window in the frame of its earliest keyframe (paper III-C).
#include <vlo/vo/optimizer.h>

#include <array>
#include <unordered_map>

#include "reprojection_error.h"

namespace vlo::vo
{
namespace
{
struct Obs
{
	KeyFrame* kf;
	std::size_t point;  ///< index into the window's points
	int idx;  ///< keypoint in kf
};
}  // namespace

BundleStats bundleAdjust(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr, int iterations,
	int refine_iterations, double chi2, const KeyFrame* gauge)
{
	BundleStats st;
	if (w.local.empty() || !w.anchor) return st;
	// Everything is written relative to the anchor: it sits at the origin with unit rotation, so the
	// numbers optimised are small wherever the window lies in the world.
	const SE3 Ta = w.anchor->Tcw, Ta_inv = Ta.inverse();
	std::unordered_map<const KeyFrame*, std::array<double, 6>> poses;
	for (auto* group : {&w.local, &w.fixed})
		for (KeyFrame* kf : *group) detail::toParams(kf->Tcw * Ta_inv, poses[kf].data());
	std::vector<std::array<double, 3>> pts(w.points.size());
	std::vector<Obs> obs;
	for (std::size_t i = 0; i < w.points.size(); ++i)
	{
		const Vec3 X = Ta * w.points[i]->pos;
		pts[i] = {X.x(), X.y(), X.z()};
		for (const auto& o : w.points[i]->observations())
			if (poses.count(o.kf)) obs.push_back({o.kf, i, o.idx});
	}
	if (obs.empty()) return st;

	auto isOutlier = [&](const Obs& o) {
		const Vec3 Xc = detail::fromParams(poses[o.kf].data()) * Vec3(pts[o.point][0], pts[o.point][1], pts[o.point][2]);
		if (Xc.z() <= 0) return true;
		const cv::KeyPoint& k = o.kf->key(o.idx);
		return (project(cam, Xc) - Vec2(k.pt.x, k.pt.y)).squaredNorm() * pyr.inv_sigma2[static_cast<std::size_t>(k.octave)] > chi2;
	};
	ceres::HuberLoss huber(std::sqrt(chi2));
	// One pass: robust over every observation, or plain squares over the current inliers.
	auto solve = [&](int its, bool robust) {
		ceres::Problem::Options po;
		po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
		ceres::Problem problem(po);
		for (const auto& o : obs)
		{
			if (!robust && isOutlier(o)) continue;
			const cv::KeyPoint& k = o.kf->key(o.idx);
			problem.AddResidualBlock(detail::ReprojectionError::create(Vec2(k.pt.x, k.pt.y),
										 pyr.inv_scale[static_cast<std::size_t>(k.octave)], cam),
				robust ? &huber : nullptr, poses[o.kf].data(), pts[o.point].data());
		}
		if (problem.NumResidualBlocks() == 0) return;
		int held = 0;
		for (KeyFrame* kf : w.fixed)
			if (problem.HasParameterBlock(poses[kf].data())) problem.SetParameterBlockConstant(poses[kf].data()), ++held;
		// Monocular gauge: without fixed keyframes, hold one (7th dof, scale, is left to damping).
		const KeyFrame* g = gauge ? gauge : (held == 0 ? w.anchor : nullptr);
		if (g && poses.count(g) && problem.HasParameterBlock(poses[g].data())) problem.SetParameterBlockConstant(poses[g].data());
		ceres::Solver::Summary summary;
		ceres::Solve(detail::solverOptions(its, true), &problem, &summary);
		if (robust) st.initial_cost = summary.initial_cost;
		st.final_cost = summary.final_cost;
	};
	if (iterations > 0) solve(iterations, true);
	if (refine_iterations > 0) solve(refine_iterations, false);

	for (const auto& o : obs)
	{
		MapPoint* mp = w.points[o.point];
		if (isOutlier(o) && !mp->bad && mp->indexIn(o.kf) == o.idx)
		{
			o.kf->points[static_cast<std::size_t>(o.idx)] = nullptr;
			mp->eraseObservation(o.kf);
			++st.outliers;
		}
	}
	for (KeyFrame* kf : w.local) kf->Tcw = detail::fromParams(poses[kf].data()) * Ta;
	for (std::size_t i = 0; i < w.points.size(); ++i)
		if (!w.points[i]->bad) w.points[i]->pos = Ta_inv * Vec3(pts[i][0], pts[i][1], pts[i][2]);
	st.keyframes = static_cast<int>(w.local.size());
	st.fixed = static_cast<int>(w.fixed.size());
	st.points = static_cast<int>(w.points.size());
	st.observations = static_cast<int>(obs.size());
	return st;
}

BundleWindow localWindow(KeyFrame* kf, int max_keyframes)
{
	BundleWindow w;
	w.local.push_back(kf);
	for (KeyFrame* n : kf->bestCovisibles(max_keyframes - 1)) w.local.push_back(n);
	const long stamp = kf->id;
	for (KeyFrame* k : w.local) k->mark_ba = stamp;
	for (KeyFrame* k : w.local)
		for (MapPoint* mp : k->points)
			if (mp && !mp->bad && mp->mark_ba != stamp)
			{
				mp->mark_ba = stamp;
				w.points.push_back(mp);
			}
	for (MapPoint* mp : w.points)
		for (const auto& o : mp->observations())
			if (o.kf->mark_ba != stamp && o.kf->mark_fixed != stamp && !o.kf->bad)
			{
				o.kf->mark_fixed = stamp;
				w.fixed.push_back(o.kf);
			}
	w.anchor = w.local.front();
	for (KeyFrame* k : w.local)
		if (k->id < w.anchor->id) w.anchor = k;
	return w;
}
}  // namespace vlo::vo
