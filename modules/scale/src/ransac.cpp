#include <vlo/scale/ransac.h>

#include <cmath>
#include <random>

namespace vlo::scale
{
RansacResult ransacMean(const std::vector<double>& s, double tolerance, int iterations, std::uint32_t seed)
{
	RansacResult r;
	const size_t n = s.size();
	if (n == 0) return r;

	auto score = [&](double h, int& count, double& dev) {
		count = 0, dev = 0;
		const double band = tolerance * std::abs(h);
		for (double x : s)
			if (std::abs(x - h) <= band) ++count, dev += std::abs(x - h);
	};
	int bestCount = -1;
	double bestDev = 0;
	auto consider = [&](size_t k) {
		int c;
		double d;
		score(s[k], c, d);
		if (c > bestCount || (c == bestCount && d < bestDev)) bestCount = c, bestDev = d, r.hypothesis = s[k];
	};
	if (n <= static_cast<size_t>(iterations))
		for (size_t k = 0; k < n; ++k) consider(k);
	else
	{
		// mt19937 output is specified by the standard; the modulo keeps the draw portable too.
		std::mt19937 rng(seed);
		for (int it = 0; it < iterations; ++it) consider(rng() % n);
	}

	r.inlier.assign(n, false);
	const double band = tolerance * std::abs(r.hypothesis);
	double sum = 0, sum2 = 0;
	for (size_t k = 0; k < n; ++k)
		if (std::abs(s[k] - r.hypothesis) <= band) r.inlier[k] = true, ++r.n_inliers, sum += s[k];
	r.mean = sum / r.n_inliers;
	for (size_t k = 0; k < n; ++k)
		if (r.inlier[k]) sum2 += (s[k] - r.mean) * (s[k] - r.mean);
	r.stddev = std::sqrt(sum2 / r.n_inliers);
	r.found = true;
	return r;
}
}  // namespace vlo::scale
