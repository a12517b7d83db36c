// Bundle adjustment of a keyframe window in the frame of its earliest keyframe (paper III-C).
#include <vlo/vo/bundle_problem.h>

#include <unordered_map>

#include "bundle_solver.h"
#include "reprojection_error.h"

namespace vlo::vo
{
BundleProblem snapshotBundle(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr, const KeyFrame* gauge)
{
	BundleProblem p;
	p.cam = cam;
	if (w.local.empty() || !w.anchor) return p;
	// Everything is written relative to the anchor: it sits at the origin with unit rotation, so the
	// numbers optimised are small wherever the window lies in the world.
	const SE3 Ta = w.anchor->Tcw;
	std::unordered_map<const KeyFrame*, std::size_t> pose_of;
	for (auto* group : {&w.local, &w.fixed})
		for (KeyFrame* kf : *group)
		{
			pose_of[kf] = p.poses.size();
			p.poses.emplace_back();
			detail::toParams(kf->Tcw * Ta.inverse(), p.poses.back().data());
		}
	p.n_local = w.local.size();
	const KeyFrame* g = gauge ? gauge : w.anchor;
	if (pose_of.count(g)) p.gauge = pose_of[g];
	p.gauge_always = gauge != nullptr;
	p.points.resize(w.points.size());
	for (std::size_t i = 0; i < w.points.size(); ++i)
	{
		const Vec3 X = Ta * w.points[i]->pos;
		p.points[i] = {X.x(), X.y(), X.z()};
		for (const auto& o : w.points[i]->observations())
		{
			const auto it = pose_of.find(o.kf);
			if (it == pose_of.end()) continue;
			const cv::KeyPoint& k = o.kf->key(o.idx);
			const auto level = static_cast<std::size_t>(k.octave);
			p.obs.push_back({it->second, i, o.idx, Vec2(k.pt.x, k.pt.y), pyr.inv_scale[level], pyr.inv_sigma2[level]});
		}
	}
	p.stats.keyframes = static_cast<int>(w.local.size());
	p.stats.fixed = static_cast<int>(w.fixed.size());
	p.stats.points = static_cast<int>(w.points.size());
	p.stats.observations = static_cast<int>(p.obs.size());
	return p;
}

namespace
{
bool isOutlier(const BundleProblem& p, const BundleProblem::Obs& o, double chi2)
{
	const auto& X = p.points[o.point];
	const Vec3 Xc = detail::fromParams(p.poses[o.pose].data()) * Vec3(X[0], X[1], X[2]);
	if (Xc.z() <= 0) return true;
	return (project(p.cam, Xc) - o.px).squaredNorm() * o.inv_sigma2 > chi2;
}

/// One pass: robust over every observation, or plain squares over the current inliers.
void solvePass(BundleProblem& p, int its, bool robust, double chi2)
{
	std::vector<char> active(p.obs.size(), 0), seen(p.poses.size(), 0);
	bool any = false;
	for (std::size_t o = 0; o < p.obs.size(); ++o)
		if (robust || !isOutlier(p, p.obs[o], chi2)) active[o] = 1, seen[p.obs[o].pose] = 1, any = true;
	if (!any) return;
	// Held: the fixed keyframes, poses without an observation in this pass, and the gauge.
	std::vector<char> held(p.poses.size(), 0);
	int fixed_seen = 0;
	for (std::size_t i = 0; i < p.poses.size(); ++i)
	{
		held[i] = i >= p.n_local || !seen[i];
		fixed_seen += i >= p.n_local && seen[i] ? 1 : 0;
	}
	// Monocular gauge: without fixed keyframes, hold one (7th dof, scale, is left to damping).
	if (p.gauge != p.npos && (p.gauge_always || fixed_seen == 0) && seen[p.gauge]) held[p.gauge] = 1;
	const detail::BundleSolveReport rep = detail::solveBundleLm(p, active, held, robust ? std::sqrt(chi2) : 0.0, its);
	if (robust) p.stats.initial_cost = rep.initial_cost;
	p.stats.final_cost = rep.final_cost;
}
}  // namespace

void solveRobust(BundleProblem& p, int iterations, double chi2)
{
	if (!p.obs.empty() && iterations > 0) solvePass(p, iterations, true, chi2);
}

void solveRefine(BundleProblem& p, int refine_iterations, double chi2)
{
	if (p.obs.empty()) return;
	if (refine_iterations > 0) solvePass(p, refine_iterations, false, chi2);
	for (auto& o : p.obs) o.outlier = isOutlier(p, o, chi2);
}

void solveBundle(BundleProblem& p, int iterations, int refine_iterations, double chi2)
{
	solveRobust(p, iterations, chi2);
	solveRefine(p, refine_iterations, chi2);
}

BundleStats applyBundle(const BundleWindow& w, const BundleProblem& p, double scale)
{
	if (p.obs.empty()) return {};
	BundleStats st = p.stats;
	const std::vector<KeyFrame*>* groups[] = {&w.local, &w.fixed};
	std::vector<KeyFrame*> kfs;
	for (const auto* g : groups) kfs.insert(kfs.end(), g->begin(), g->end());
	for (const auto& o : p.obs)
	{
		MapPoint* mp = w.points[o.point];
		KeyFrame* kf = kfs[o.pose];
		if (o.outlier && !mp->bad && mp->indexIn(kf) == o.idx)
		{
			kf->points[static_cast<std::size_t>(o.idx)] = nullptr;
			mp->eraseObservation(kf);
			++st.outliers;
		}
	}
	const SE3 Ta = w.anchor->Tcw, Ta_inv = Ta.inverse();
	for (std::size_t i = 0; i < p.n_local; ++i)
	{
		SE3 T = detail::fromParams(p.poses[i].data());
		T.translation() *= scale;
		kfs[i]->Tcw = T * Ta;
	}
	for (std::size_t i = 0; i < w.points.size(); ++i)
		if (!w.points[i]->bad) w.points[i]->pos = Ta_inv * (scale * Vec3(p.points[i][0], p.points[i][1], p.points[i][2]));
	return st;
}

BundleStats bundleAdjust(const BundleWindow& w, const PinholeCamera& cam, const ScalePyramid& pyr, int iterations,
	int refine_iterations, double chi2, const KeyFrame* gauge)
{
	BundleProblem p = snapshotBundle(w, cam, pyr, gauge);
	solveBundle(p, iterations, refine_iterations, chi2);
	return applyBundle(w, p);
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
