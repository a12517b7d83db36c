// ORB extraction: count, spread over the image, determinism, repeatability; anms/quadtree vs cv::ORB.
#include <gtest/gtest.h>
#include <vlo/vo/orb_extractor.h>

#include "../src/feature_distribution.h"
#include "synthetic_scene.h"

#include <random>

using namespace vlo;
using namespace vlo::vo;

namespace
{
/// Fraction of 8x4 image cells that hold at least 1% of the features.
double coverage(const Features& f)
{
	int cells[32] = {0};
	for (const auto& k : f.keys) ++cells[std::min(3, int(k.pt.y * 4 / f.height)) * 8 + std::min(7, int(k.pt.x * 8 / f.width))];
	int covered = 0;
	for (int c : cells) covered += c >= 0.01 * f.size();
	return covered / 32.0;
}

cv::Mat streetImage()
{
	const auto cam = test::kittiCamera();
	return test::StreetRenderer(test::StreetScene(), cam).render(test::drivePose(0));
}
}  // namespace

TEST(Orb, ExtractorSpreadsFeaturesOverLevels)
{
	const cv::Mat img = streetImage();
	OrbOptions opt;
	const Features f = OrbExtractor(opt).extract(img);
	EXPECT_GT(f.size(), 0.9 * opt.n_features);
	EXPECT_LE(f.size(), static_cast<std::size_t>(opt.n_features));
	EXPECT_EQ(f.descriptors.rows, static_cast<int>(f.size()));
	EXPECT_EQ(f.descriptors.cols, 32);
	int levels[8] = {0};
	for (const auto& k : f.keys)
	{
		ASSERT_GE(k.octave, 0);
		ASSERT_LT(k.octave, 8);
		++levels[k.octave];
		EXPECT_GE(k.pt.x, opt.edge_threshold - 1);
		EXPECT_LT(k.pt.x, img.cols - opt.edge_threshold + 1);
	}
	for (int l = 0; l < 8; ++l) EXPECT_GT(levels[l], 0) << "level " << l;
	EXPECT_GT(coverage(f), 0.7);
	// Window queries find what is there.
	const auto& k = f.keys[f.size() / 2];
	const auto near = f.grid.inArea(k.pt.x, k.pt.y, 1.0);
	EXPECT_NE(std::find(near.begin(), near.end(), static_cast<int>(f.size() / 2)), near.end());
}

TEST(Orb, DeterministicAndAsSpreadAsOpenCv)
{
	const cv::Mat img = streetImage();
	OrbOptions grid, ocv;
	ocv.detector = "opencv";
	const Features a = OrbExtractor(grid).extract(img), b = OrbExtractor(grid).extract(img);
	ASSERT_EQ(a.size(), b.size());
	EXPECT_EQ(cv::norm(a.descriptors, b.descriptors, cv::NORM_HAMMING), 0);
	const Features c = OrbExtractor(ocv).extract(img);
	EXPECT_GT(c.size(), 0u);
	EXPECT_GE(coverage(a), coverage(c));
}

TEST(Orb, BlankImageGivesNoFeatures)
{
	const cv::Mat blank(376, 1241, CV_8U, cv::Scalar(128));
	for (const char* d : {"anms", "quadtree", "opencv"})
	{
		OrbOptions opt;
		opt.detector = d;
		const Features f = OrbExtractor(opt).extract(blank);
		EXPECT_EQ(f.size(), 0u) << d;
		EXPECT_TRUE(f.grid.inArea(100, 100, 50).empty());
	}
}

// The word-parallel bit count against counting bit by bit, up to descriptors that differ everywhere.
TEST(Orb, HammingCountsEveryDifferingBit)
{
	cv::RNG rng(7);
	uint8_t a[32], b[32];
	for (int trial = 0; trial < 200; ++trial)
	{
		for (int i = 0; i < 32; ++i)
		{
			a[i] = static_cast<uint8_t>(rng.uniform(0, 256));
			// The last trials: complements (256 bits), then copies (0 bits).
			b[i] = trial == 198 ? static_cast<uint8_t>(~a[i]) : trial == 199 ? a[i]
																			 : static_cast<uint8_t>(rng.uniform(0, 256));
		}
		int bits = 0;
		for (int i = 0; i < 32; ++i)
			for (int k = 0; k < 8; ++k) bits += ((a[i] ^ b[i]) >> k) & 1;
		ASSERT_EQ(bits, hamming(a, b)) << "trial " << trial;
	}
	a[0] = 0, b[0] = 0xff;  // no other way to reach 256 than the complement
	for (int i = 1; i < 32; ++i) b[i] = static_cast<uint8_t>(~a[i]);
	EXPECT_EQ(256, hamming(a, b));
}

TEST(Orb, CornersSortStrongestFirstAsTheComparatorDoes)
{
	// Ties of response broken by position, as FAST's integer scores on a pixel grid give by the
	// thousand; and a few negative and fractional values the comparator orders as well.
	std::mt19937 rng(3);
	std::vector<cv::KeyPoint> kps;
	for (int i = 0; i < 5000; ++i)
		kps.emplace_back(cv::Point2f(float(rng() % 200), float(rng() % 100)), 7.f, -1.f, float(rng() % 30));
	kps.emplace_back(cv::Point2f(-1.5f, 2.25f), 7.f, -1.f, -3.f);
	kps.emplace_back(cv::Point2f(0.f, -0.5f), 7.f, -1.f, 12.5f);
	auto expected = kps;
	std::stable_sort(expected.begin(), expected.end(), detail::stronger);
	detail::sortStrongestFirst(kps);
	ASSERT_EQ(kps.size(), expected.size());
	for (std::size_t i = 0; i < kps.size(); ++i)
	{
		EXPECT_EQ(kps[i].pt, expected[i].pt) << i;
		EXPECT_EQ(kps[i].response, expected[i].response) << i;
	}
}
