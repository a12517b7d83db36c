// Keypoint selection: the tests in order, one keypoint per NMS cell, the strongest, spread out.
#include <gtest/gtest.h>
#include <vlo/scale/keypoint_tests.h>
#include <vlo/scale/selection.h>

#include <opencv2/imgproc.hpp>

#include <map>
#include <set>

using namespace vlo::scale;

namespace
{
cv::Mat texture(int w, int h, int seed)
{
	cv::Mat img(h, w, CV_8U);
	cv::RNG rng(seed);
	rng.fill(img, cv::RNG::UNIFORM, 0, 256);
	cv::GaussianBlur(img, img, cv::Size(0, 0), 1.5);
	return img;
}

/// Every pixel (with a sub-pixel offset) of a region as a projected point.
std::vector<DepthPixel> everyPixel(cv::Rect r)
{
	std::vector<DepthPixel> out;
	for (int y = r.y; y < r.y + r.height; ++y)
		for (int x = r.x; x < r.x + r.width; ++x)
			out.push_back({{x + 0.2f, y - 0.3f}, 10.f, static_cast<int>(out.size())});
	return out;
}
}  // namespace

TEST(Selection, OneKeypointPerCellTheStrongestGradient)
{
	const cv::Mat img = texture(320, 240, 1);
	const auto pts = everyPixel({8, 8, 304, 224});
	ScaleOptions opt;
	opt.keypoint_test = KeypointTest::Fast9;
	opt.fast_threshold = 8;
	opt.gradient_threshold = 2;
	opt.nms_cell = 16;
	opt.max_keypoints = 10000;
	SelectionCounts n;
	const auto kps = selectKeypoints(img, pts, opt, &n);

	// Brute force reference: best gradient per cell among pixels passing both tests.
	std::map<int, float> best;
	int corner = 0, grad = 0;
	for (const auto& p : pts)
	{
		const int x = cvRound(p.px.x), y = cvRound(p.px.y);
		if (!fast9(img, x, y, opt.fast_threshold)) continue;
		++corner;
		const cv::Point2f g = sobelGradient(img, x, y);
		if (std::sqrt(g.dot(g)) <= opt.gradient_threshold) continue;
		++grad;
		float& b = best[(y / 16) * 100 + x / 16];
		b = std::max(b, std::sqrt(g.dot(g)));
	}
	EXPECT_EQ(n.corner, corner);
	EXPECT_EQ(n.gradient, grad);
	ASSERT_EQ(kps.size(), best.size());
	std::set<int> cells;
	for (size_t i = 0; i < kps.size(); ++i)
	{
		const auto& p = pts[kps[i].projected].px;
		const int cell = (cvRound(p.y) / 16) * 100 + cvRound(p.x) / 16;
		EXPECT_TRUE(cells.insert(cell).second) << "two keypoints in one cell";
		EXPECT_FLOAT_EQ(kps[i].score, best[cell]);
		if (i == 0) continue;
		EXPECT_GE(kps[i - 1].score, kps[i].score);  // strongest first
	}
	// Spread: nearly every one of the 20 x 15 cells holds a keypoint on this texture.
	EXPECT_GE(static_cast<int>(kps.size()), 0.9 * 20 * 15);
}

TEST(Selection, NmsSpreadsADenseClusterAndTheCapKeepsTheStrongest)
{
	const cv::Mat img = texture(320, 240, 2);
	// A dense block of LiDAR points (4096 of them, in 2 x 2 cells) and a sparse grid elsewhere.
	auto pts = everyPixel({32, 32, 64, 64});
	for (int y = 8; y < 232; y += 8)
		for (int x = 104; x < 312; x += 8) pts.push_back({{float(x), float(y)}, 10.f, static_cast<int>(pts.size())});
	ScaleOptions opt;
	opt.keypoint_test = KeypointTest::None;
	opt.gradient_threshold = 0;
	opt.nms_cell = 32;
	opt.max_keypoints = 10000;
	const auto all = selectKeypoints(img, pts, opt);
	std::set<int> occupied;
	for (const auto& p : pts) occupied.insert((cvRound(p.px.y) / 32) * 100 + cvRound(p.px.x) / 32);
	EXPECT_EQ(all.size(), occupied.size());  // one per occupied cell: 4 + 7 x 8
	EXPECT_EQ(all.size(), 60u);
	int inBlock = 0;
	for (const auto& k : all) inBlock += pts[k.projected].px.x < 100;
	EXPECT_EQ(inBlock, 4);

	opt.max_keypoints = 20;
	const auto capped = selectKeypoints(img, pts, opt);
	ASSERT_EQ(capped.size(), 20u);
	for (size_t i = 0; i < capped.size(); ++i) EXPECT_EQ(capped[i].projected, all[i].projected);
}

TEST(Selection, GradientThresholdAndCornerTestFilter)
{
	cv::Mat flat(100, 100, CV_8U, cv::Scalar(90));
	const auto pts = everyPixel({10, 10, 80, 80});
	ScaleOptions opt;
	opt.keypoint_test = KeypointTest::None;
	EXPECT_TRUE(selectKeypoints(flat, pts, opt).empty());  // no gradient anywhere
	// A bright square: corners pass FAST-9, straight edges do not.
	flat(cv::Rect(40, 40, 20, 20)).setTo(200);
	opt.keypoint_test = KeypointTest::Fast9;
	opt.nms_cell = 1;
	SelectionCounts n;
	const auto kps = selectKeypoints(flat, pts, opt, &n);
	ASSERT_FALSE(kps.empty());
	for (const auto& k : kps)
	{
		const cv::Point2f p = pts[k.projected].px;
		const bool nearCorner = (std::abs(p.x - 40) < 4 || std::abs(p.x - 59) < 4) && (std::abs(p.y - 40) < 4 || std::abs(p.y - 59) < 4);
		EXPECT_TRUE(nearCorner) << p;
	}
	opt.keypoint_test = KeypointTest::None;
	EXPECT_GT(selectKeypoints(flat, pts, opt).size(), 4 * kps.size());  // edges pass the gradient test alone
}
