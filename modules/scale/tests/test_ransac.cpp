// RANSAC over s_j: the mean of the inliers survives a large share of outliers.
#include <gtest/gtest.h>
#include <vlo/scale/ransac.h>

#include <random>

using namespace vlo::scale;

namespace
{
std::vector<double> samples(int inliers, int outliers, double truth, unsigned seed)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> in(truth, 0.005 * truth);
	std::uniform_real_distribution<double> out(0.2, 5.0);
	std::vector<double> s;
	for (int i = 0; i < inliers; ++i) s.push_back(in(rng));
	for (int i = 0; i < outliers; ++i) s.push_back(out(rng));
	std::shuffle(s.begin(), s.end(), rng);
	return s;
}
}  // namespace

TEST(Ransac, MeanOfInliersDespiteFortyPercentOutliers)
{
	const auto s = samples(100, 70, 1.25, 1);
	for (int iterations : {500, 50})  // exhaustive, then sampled
	{
		const RansacResult r = ransacMean(s, 0.05, iterations, 7);
		ASSERT_TRUE(r.found);
		EXPECT_NEAR(r.mean, 1.25, 0.003) << iterations;
		EXPECT_LT(r.stddev, 0.015);  // 0.00625 from the inliers, plus the outliers inside the band
		EXPECT_GE(r.n_inliers, 100);
		EXPECT_LE(r.n_inliers, 106);  // a few uniform outliers fall inside the 5 % band
		int flagged = 0;
		for (bool b : r.inlier) flagged += b;
		EXPECT_EQ(flagged, r.n_inliers);
	}
	// The plain mean is useless here.
	double mean = 0;
	for (double x : s) mean += x / s.size();
	EXPECT_GT(std::abs(mean - 1.25), 0.3);
}

TEST(Ransac, DeterministicForASeedAndExhaustiveWhenFewSamples)
{
	const auto s = samples(300, 300, 0.8, 2);
	const RansacResult a = ransacMean(s, 0.05, 100, 11), b = ransacMean(s, 0.05, 100, 11);
	EXPECT_EQ(a.mean, b.mean);
	EXPECT_EQ(a.inlier, b.inlier);
	EXPECT_NEAR(a.mean, 0.8, 0.003);
	// Exhaustive search does not depend on the seed at all.
	const auto few = samples(30, 20, 2.0, 3);
	EXPECT_EQ(ransacMean(few, 0.05, 200, 1).mean, ransacMean(few, 0.05, 200, 99).mean);
}

TEST(Ransac, TiesGoToTheTighterCluster)
{
	// Two clusters of 3: the tighter one wins.
	const std::vector<double> s = {1.00, 1.001, 0.999, 2.0, 2.06, 1.95};
	const RansacResult r = ransacMean(s, 0.05, 100, 1);
	EXPECT_EQ(r.n_inliers, 3);
	EXPECT_NEAR(r.mean, 1.0, 1e-9);
}

TEST(Ransac, EmptyAndSingle)
{
	EXPECT_FALSE(ransacMean({}, 0.05, 10, 1).found);
	const RansacResult one = ransacMean({1.7}, 0.05, 10, 1);
	EXPECT_TRUE(one.found);
	EXPECT_EQ(one.mean, 1.7);
	EXPECT_EQ(one.n_inliers, 1);
}
