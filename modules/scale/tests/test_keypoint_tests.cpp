// FAST-9, the FAST-12 pre-test and the gradient on hand-built patches; FAST-9 against OpenCV's FAST.
#include <gtest/gtest.h>
#include <vlo/scale/keypoint_tests.h>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdio>
#include <initializer_list>
#include <vector>

using namespace vlo::scale;

namespace
{
/// 15x15 patch of grey `base`, centre (7, 7), with the listed circle pixels set to `value`.
cv::Mat patch(int base, std::initializer_list<int> circle, int value)
{
	cv::Mat m(15, 15, CV_8U, cv::Scalar(base));
	for (int k : circle) m.at<uchar>(7 + kFastCircle[k].y, 7 + kFastCircle[k].x) = static_cast<uchar>(value);
	return m;
}
}  // namespace

TEST(Fast9, CircleIsTheBresenhamCircleOfRadius3)
{
	for (const auto& p : kFastCircle)
	{
		const double r = std::hypot(p.x, p.y);
		EXPECT_GE(r, 2.8);
		EXPECT_LE(r, 3.2);
	}
	EXPECT_EQ(kFastCircle[0], cv::Point(0, -3));  // compass pixels of the pre-test
	EXPECT_EQ(kFastCircle[4], cv::Point(3, 0));
	EXPECT_EQ(kFastCircle[8], cv::Point(0, 3));
	EXPECT_EQ(kFastCircle[12], cv::Point(-3, 0));
}

TEST(Fast9, NineContiguousBrighterOrDarkerIsACorner)
{
	EXPECT_FALSE(fast9(patch(100, {}, 0), 7, 7, 20));  // flat
	EXPECT_TRUE(fast9(patch(100, {0, 1, 2, 3, 4, 5, 6, 7, 8}, 130), 7, 7, 20));  // 9 brighter
	EXPECT_TRUE(fast9(patch(100, {3, 4, 5, 6, 7, 8, 9, 10, 11}, 60), 7, 7, 20));  // 9 darker
	EXPECT_FALSE(fast9(patch(100, {0, 1, 2, 3, 4, 5, 6, 7}, 130), 7, 7, 20));  // only 8
	EXPECT_TRUE(fast9(patch(100, {12, 13, 14, 15, 0, 1, 2, 3, 4}, 130), 7, 7, 20));  // across the wrap
	EXPECT_FALSE(fast9(patch(100, {0, 2, 4, 6, 8, 10, 12, 14, 1}, 130), 7, 7, 20));  // 9, not contiguous
	// The difference must exceed the threshold strictly (as in OpenCV).
	EXPECT_FALSE(fast9(patch(100, {0, 1, 2, 3, 4, 5, 6, 7, 8}, 120), 7, 7, 20));
	EXPECT_TRUE(fast9(patch(100, {0, 1, 2, 3, 4, 5, 6, 7, 8}, 121), 7, 7, 20));
	// A bright dot on a dark ground: the whole circle is darker.
	cv::Mat dot(15, 15, CV_8U, cv::Scalar(40));
	dot.at<uchar>(7, 7) = 200;
	EXPECT_TRUE(fast9(dot, 7, 7, 20));
}

// The compass pre-check inside fast9 must not lose a run: every arc of 9-16 from every start is a
// corner (brighter and darker), every arc of 8 is not.
TEST(Fast9, EveryArcOfNineOrMoreIsACornerWhereverItStarts)
{
	for (int start = 0; start < 16; ++start)
		for (int len = 8; len <= 16; ++len)
		{
			std::vector<int> arc;
			for (int k = 0; k < len; ++k) arc.push_back((start + k) % 16);
			for (int value : {130, 70})
			{
				cv::Mat m(15, 15, CV_8U, cv::Scalar(100));
				for (int k : arc) m.at<uchar>(7 + kFastCircle[k].y, 7 + kFastCircle[k].x) = static_cast<uchar>(value);
				EXPECT_EQ(fast9(m, 7, 7, 20), len >= 9) << "start " << start << " length " << len << " value " << value;
			}
		}
}

TEST(Fast9, AgreesWithOpenCvFastEverywhere)
{
	cv::Mat img(120, 160, CV_8U);
	cv::RNG rng(4);
	rng.fill(img, cv::RNG::UNIFORM, 0, 256);
	cv::GaussianBlur(img, img, cv::Size(0, 0), 1.2);
	for (int t : {5, 10, 20})
	{
		std::vector<cv::KeyPoint> kps;
		cv::FAST(img, kps, t, false, cv::FastFeatureDetector::TYPE_9_16);
		cv::Mat ref(img.size(), CV_8U, cv::Scalar(0));
		for (const auto& k : kps) ref.at<uchar>(cvRound(k.pt.y), cvRound(k.pt.x)) = 1;
		int ours = 0, agree = 0;
		for (int y = 3; y < img.rows - 3; ++y)
			for (int x = 3; x < img.cols - 3; ++x)
			{
				const bool c = fast9(img, x, y, t);
				ours += c;
				agree += c == (ref.at<uchar>(y, x) == 1);
			}
		EXPECT_EQ(agree, (img.rows - 6) * (img.cols - 6)) << "threshold " << t;
		EXPECT_EQ(ours, static_cast<int>(kps.size()));
		EXPECT_GT(ours, 50);
	}
}

TEST(Fast12Pretest, ThreeOfTheFourCompassPixels)
{
	// Compass pixels: 0 top, 4 right, 8 bottom, 12 left.
	for (bool same : {false, true})
	{
		EXPECT_TRUE(fast12Pretest(patch(100, {0, 4, 8}, 130), 7, 7, 20, 3, same));
		EXPECT_TRUE(fast12Pretest(patch(100, {0, 4, 8, 12}, 60), 7, 7, 20, 3, same));
		EXPECT_FALSE(fast12Pretest(patch(100, {0, 4}, 130), 7, 7, 20, 3, same));  // 2 of 4
		// Other circle pixels do not count, however many.
		EXPECT_FALSE(fast12Pretest(patch(100, {1, 2, 3, 5, 6, 7, 9, 10, 11, 13, 14, 15}, 130), 7, 7, 20, 3, same));
		// min_count 4 is the literal "more than three".
		EXPECT_FALSE(fast12Pretest(patch(100, {0, 4, 8}, 130), 7, 7, 20, 4, same));
		EXPECT_TRUE(fast12Pretest(patch(100, {0, 4, 8, 12}, 130), 7, 7, 20, 4, same));
		// Strict threshold.
		EXPECT_FALSE(fast12Pretest(patch(100, {0, 4, 8}, 120), 7, 7, 20, 3, same));
	}
	// 2 brighter + 1 darker: three differences beyond t, but not on one side.
	cv::Mat mixed = patch(100, {0, 4}, 130);
	mixed.at<uchar>(7 + 3, 7) = 60;
	EXPECT_TRUE(fast12Pretest(mixed, 7, 7, 20, 3, false));
	EXPECT_FALSE(fast12Pretest(mixed, 7, 7, 20, 3, true));
	// A straight edge fails either way: left darker, right brighter, top and bottom equal.
	cv::Mat edge(15, 15, CV_8U, cv::Scalar(50));
	edge(cv::Rect(8, 0, 7, 15)).setTo(150);
	edge.col(7).setTo(100);
	EXPECT_FALSE(fast12Pretest(edge, 7, 7, 20, 3, false));
}

TEST(Fast12Pretest, AnySignIsTheRelaxationSameSignIsNot)
{
	cv::Mat img(120, 160, CV_8U);
	cv::RNG rng(9);
	rng.fill(img, cv::RNG::UNIFORM, 0, 256);
	cv::GaussianBlur(img, img, cv::Size(0, 0), 1.5);
	int n9 = 0, any = 0, same = 0;
	for (int y = 3; y < img.rows - 3; ++y)
		for (int x = 3; x < img.cols - 3; ++x)
		{
			n9 += fast9(img, x, y, 10);
			any += fast12Pretest(img, x, y, 10, 3, false);
			same += fast12Pretest(img, x, y, 10, 3, true);
		}
	std::printf("pixels passing at t = 10: FAST-9 %d, pre-test any sign %d, same sign %d\n", n9, any, same);
	EXPECT_GT(any, n9 * 3 / 2);  // more candidates from few LiDAR rows: the point of the relaxed test
	EXPECT_LT(same, n9 * 6 / 5);  // about as selective as FAST-9 (fewer on the street scene)
}

TEST(Gradient, SobelOverEightIsTheSlopeOfARamp)
{
	cv::Mat ramp(9, 9, CV_8U);
	for (int y = 0; y < 9; ++y)
		for (int x = 0; x < 9; ++x) ramp.at<uchar>(y, x) = static_cast<uchar>(10 + 7 * x + 3 * y);
	const cv::Point2f g = sobelGradient(ramp, 4, 4);
	EXPECT_FLOAT_EQ(g.x, 7);
	EXPECT_FLOAT_EQ(g.y, 3);
	const cv::Point2f gi = gradientAt(ramp, {4.3f, 3.6f});
	EXPECT_NEAR(gi.x, 7, 1e-5);
	EXPECT_NEAR(gi.y, 3, 1e-5);
	// A vertical step: the gradient points across it, halfway between two pixels' responses.
	cv::Mat step(9, 9, CV_8U, cv::Scalar(50));
	step(cv::Rect(5, 0, 4, 9)).setTo(150);
	EXPECT_FLOAT_EQ(sobelGradient(step, 4, 4).x, 50);  // (150 - 50) * 4 / 8
	EXPECT_FLOAT_EQ(sobelGradient(step, 4, 4).y, 0);
	EXPECT_FLOAT_EQ(gradientAt(step, {4.5f, 4.f}).x, 50);
}
