// RingSearch against a brute-force search of the same ring: the same point and distance for
// queries near and far, above and below the rings, with and without a best distance to beat.
#include <gtest/gtest.h>
#include <vlo/loam/ring_search.h>

#include <cmath>
#include <limits>
#include <random>

namespace vlo::loam::test
{
namespace
{
/// 16 rings 2 degrees apart with 0.05 degree jitter, 600 returns each at 2-60 m, in sweep order.
ScanPoints sweep(std::mt19937& rng)
{
	std::uniform_real_distribution<float> range(2.0f, 60.0f), jitter(-0.05f, 0.05f);
	ScanPoints pts;
	for (int ring = 0; ring < 16; ++ring)
		for (int k = 0; k < 600; ++k)
		{
			const float az = -3.14159f + 6.28318f * k / 600.0f, el = (-15.0f + 2.0f * ring + jitter(rng)) * 3.14159f / 180.0f;
			const float r = range(rng);
			ScanPoint p;
			p.p = r * Eigen::Vector3f(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
			p.ring = ring;
			pts.push_back(p);
		}
	return pts;
}

/// The closest point of `ring` within sqrt(best_d2) among those less than 90 degrees of azimuth away
/// from q (what RingSearch::nearest searches), or -1.
int bruteForce(const ScanPoints& pts, int ring, const Eigen::Vector3f& q, float& best_d2, int exclude)
{
	int best = -1;
	for (std::size_t i = 0; i < pts.size(); ++i)
	{
		const Eigen::Vector3f& p = pts[i].p;
		if (pts[i].ring != ring || static_cast<int>(i) == exclude || q.x() * p.x() + q.y() * p.y() <= 0) continue;
		const float dx = p.x() - q.x(), dy = p.y() - q.y(), dz = p.z() - q.z();  // in RingSearch's order
		const float d2 = dx * dx + dy * dy + dz * dz;
		if (d2 < best_d2) best_d2 = d2, best = static_cast<int>(i);
	}
	return best;
}
}  // namespace

TEST(RingSearch, NearestIsTheBruteForceNearest)
{
	std::mt19937 rng(5);
	const ScanPoints pts = sweep(rng);
	RingSearch search;
	search.build(pts, 16);
	std::uniform_real_distribution<float> xy(-60.0f, 60.0f), z(-12.0f, 8.0f), unit(0.0f, 1.0f);
	int found = 0, skipped_rings = 0;
	for (int k = 0; k < 3000; ++k)
	{
		// Half the queries next to a return (as in a scan pair), half anywhere.
		Eigen::Vector3f q(xy(rng), xy(rng), z(rng));
		if (k % 2 == 0) q = pts[static_cast<std::size_t>(k * 7) % pts.size()].p + 0.3f * Eigen::Vector3f(unit(rng), unit(rng), unit(rng));
		const RingSearch::Query query(q);
		const float start = k % 3 == 0 ? std::numeric_limits<float>::infinity() : 25.0f * unit(rng);
		const int exclude = k % 5 == 0 ? k * 7 % static_cast<int>(pts.size()) : -1;
		for (int ring = 0; ring < 16; ++ring)
		{
			float d_fast = start, d_brute = start;
			const int fast = search.nearest(ring, query, d_fast, exclude);
			const int brute = bruteForce(pts, ring, q, d_brute, exclude);
			ASSERT_EQ(brute, fast) << "query " << k << " ring " << ring;
			ASSERT_EQ(d_brute, d_fast) << "query " << k << " ring " << ring;
			found += fast >= 0;
			skipped_rings += fast < 0;
		}
	}
	// Both outcomes are exercised.
	EXPECT_GT(found, 10000);
	EXPECT_GT(skipped_rings, 5000);
}
}  // namespace vlo::loam::test
