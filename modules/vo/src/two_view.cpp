// RANSAC over homography and fundamental matrix, model selection and motion choice.
#include <vlo/core/se3.h>
#include <vlo/vo/two_view.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace vlo::vo
{
namespace
{
std::string fmt(const char* f, double a, double b)
{
	char buf[160];
	std::snprintf(buf, sizeof(buf), f, a, b);
	return buf;
}

/// The same random minimal sets serve both models so that their scores are comparable.
std::vector<std::vector<int>> randomSets(int n, int iterations, int seed)
{
	std::mt19937 rng(static_cast<unsigned>(seed));
	std::vector<std::vector<int>> sets(static_cast<std::size_t>(iterations));
	std::vector<int> all(static_cast<std::size_t>(n));
	for (auto& s : sets)
	{
		for (int i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
		int avail = n;
		for (int k = 0; k < 8; ++k)
		{
			const int r = static_cast<int>(rng() % static_cast<unsigned>(avail));
			s.push_back(all[static_cast<std::size_t>(r)]);
			all[static_cast<std::size_t>(r)] = all[static_cast<std::size_t>(--avail)];
		}
	}
	return sets;
}

template <class Fit, class Score>
double ransac(const std::vector<std::vector<int>>& sets, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2,
	double sigma, Fit fit, Score score, Mat3& best, std::vector<char>& best_inliers)
{
	double best_score = 0;
	std::vector<Vec2> s1(8), s2(8);
	std::vector<char> inl;
	for (const auto& set : sets)
	{
		for (int k = 0; k < 8; ++k) s1[k] = x1[static_cast<std::size_t>(set[k])], s2[k] = x2[static_cast<std::size_t>(set[k])];
		const Mat3 M = fit(s1, s2);
		if (!M.allFinite()) continue;
		const double sc = score(M, x1, x2, sigma, inl);
		if (sc > best_score) best_score = sc, best = M, best_inliers = inl;
	}
	return best_score;
}
}  // namespace

TwoViewResult reconstructTwoView(
	const PinholeCamera& cam, const std::vector<Vec2>& x1, const std::vector<Vec2>& x2, const InitOptions& opt)
{
	TwoViewResult res;
	const int n = static_cast<int>(x1.size());
	if (n < 8)
	{
		res.reason = "too few matches for two-view geometry (" + std::to_string(n) + " < 8)";
		return res;
	}
	const auto sets = randomSets(n, opt.ransac_iterations, opt.seed);
	Mat3 H = Mat3::Identity(), F = Mat3::Zero();
	std::vector<char> inl_h(x1.size(), 0), inl_f(x1.size(), 0);
	const double sh = ransac(sets, x1, x2, opt.sigma, detail::homographyDLT, detail::scoreHomography, H, inl_h);
	const double sf = ransac(sets, x1, x2, opt.sigma, detail::fundamental8, detail::scoreFundamental, F, inl_f);
	if (sh + sf <= 0)
	{
		res.reason = "no consistent two-view model";
		return res;
	}
	res.rh = sh / (sh + sf);
	const Mat3 K = cam.K();
	std::vector<detail::Motion> motions;
	const std::vector<char>* inliers = nullptr;
	if (res.rh > opt.homography_ratio)
	{
		res.model = 'H';
		motions = detail::decomposeHomography(H, K);
		inliers = &inl_h;
	}
	else
	{
		res.model = 'F';
		motions = detail::decomposeEssential(K.transpose() * F * K);
		inliers = &inl_f;
	}
	res.n_inliers = static_cast<int>(std::count(inliers->begin(), inliers->end(), 1));

	const double th2 = 4.0 * opt.sigma * opt.sigma;
	std::vector<detail::CheckResult> checks;
	for (const auto& m : motions) checks.push_back(detail::checkMotion(m, x1, x2, *inliers, K, th2));
	if (checks.empty())
	{
		res.reason = "homography without translation";
		return res;
	}
	std::size_t best = 0;
	for (std::size_t i = 1; i < checks.size(); ++i)
		if (checks[i].n_good > checks[best].n_good) best = i;
	std::size_t second = checks.size();  // the strongest competitor
	for (std::size_t i = 0; i < checks.size(); ++i)
		if (i != best && (second == checks.size() || checks[i].n_good > checks[second].n_good)) second = i;
	const auto competes = [&](std::size_t i) { return i < checks.size() && checks[i].n_good > opt.ambiguity_ratio * checks[best].n_good; };
	if (res.model == 'H' && competes(second) && opt.planar_rotation_margin_deg > 0)
	{
		// Twofold planar ambiguity: prefer the clearly smaller rotation among the competitors.
		std::size_t least = best;
		for (std::size_t i = 0; i < checks.size(); ++i)
			if (competes(i) && rotationAngle(motions[i].R) < rotationAngle(motions[least].R)) least = i;
		bool clear = true;
		for (std::size_t i = 0; i < checks.size(); ++i)
			if (i != least && (competes(i) || i == best) &&
				rotationAngle(motions[i].R) - rotationAngle(motions[least].R) < opt.planar_rotation_margin_deg * M_PI / 180)
				clear = false;
		if (clear)
		{
			best = least;
			second = checks.size();
		}
	}
	const auto& b = checks[best];
	const int second_good = second < checks.size() ? checks[second].n_good : 0;
	res.n_good = b.n_good;
	res.parallax_deg = b.parallax_deg;
	const int min_good = std::max(static_cast<int>(opt.min_good_fraction * res.n_inliers), opt.min_triangulated);
	const std::string tag = std::string(1, res.model) + ": ";
	if (b.n_good < min_good)
		res.reason = tag + fmt("too few points triangulated (%.0f of %.0f inliers)", b.n_good, res.n_inliers);
	else if (b.parallax_deg < opt.min_parallax_deg)
		res.reason = tag + fmt("too little parallax (%.2f < %.2f deg)", b.parallax_deg, opt.min_parallax_deg);
	else if (second_good > opt.ambiguity_ratio * b.n_good)
		res.reason = tag + fmt("ambiguous motion (%.0f vs %.0f points)", second_good, b.n_good);
	else
	{
		res.ok = true;
		res.T21 = makeSE3(motions[best].R, motions[best].t);
		res.points = b.points;
		res.good = b.good;
	}
	return res;
}
}  // namespace vlo::vo
