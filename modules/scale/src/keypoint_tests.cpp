#include <vlo/scale/keypoint_tests.h>

#include <cmath>
#include <cstdint>

namespace vlo::scale
{
const std::array<cv::Point, 16> kFastCircle = {{{0, -3}, {1, -3}, {2, -2}, {3, -1}, {3, 0}, {3, 1}, {2, 2},
	{1, 3}, {0, 3}, {-1, 3}, {-2, 2}, {-3, 1}, {-3, 0}, {-3, -1}, {-2, -2}, {-1, -3}}};

namespace
{
/// True when the 16-bit circular mask holds a run of at least n ones.
bool hasCircularRun(std::uint32_t mask16, int n)
{
	const std::uint32_t m = mask16 | (mask16 << 16);  // unrolled once: runs across the wrap
	std::uint32_t r = m;
	for (int k = 1; k < n; ++k) r &= m >> k;
	return (r & 0xFFFFu) != 0;
}
}  // namespace

bool fast9(const cv::Mat& img, int x, int y, int threshold)
{
	const int c = img.at<std::uint8_t>(y, x);
	// Any 9 contiguous of the 16 hold at least two of the four compass pixels (0, 4, 8, 12): with
	// fewer than two brighter and fewer than two darker there is no run (most pixels stop here).
	int compass_brighter = 0, compass_darker = 0;
	for (int k = 0; k < 16; k += 4)
	{
		const int v = img.at<std::uint8_t>(y + kFastCircle[k].y, x + kFastCircle[k].x);
		compass_brighter += v > c + threshold;
		compass_darker += v < c - threshold;
	}
	if (compass_brighter < 2 && compass_darker < 2) return false;
	std::uint32_t brighter = 0, darker = 0;
	for (int k = 0; k < 16; ++k)
	{
		const int v = img.at<std::uint8_t>(y + kFastCircle[k].y, x + kFastCircle[k].x);
		if (v > c + threshold) brighter |= 1u << k;
		else if (v < c - threshold) darker |= 1u << k;
	}
	return hasCircularRun(brighter, 9) || hasCircularRun(darker, 9);
}

bool fast12Pretest(const cv::Mat& img, int x, int y, int threshold, int min_count, bool same_sign)
{
	const int c = img.at<std::uint8_t>(y, x);
	int brighter = 0, darker = 0;
	for (int k = 0; k < 16; k += 4)
	{
		const int v = img.at<std::uint8_t>(y + kFastCircle[k].y, x + kFastCircle[k].x);
		brighter += v > c + threshold;
		darker += v < c - threshold;
	}
	return same_sign ? (brighter >= min_count || darker >= min_count) : brighter + darker >= min_count;
}

cv::Point2f sobelGradient(const cv::Mat& img, int x, int y)
{
	auto I = [&](int dx, int dy) { return static_cast<int>(img.at<std::uint8_t>(y + dy, x + dx)); };
	const int gx = (I(1, -1) + 2 * I(1, 0) + I(1, 1)) - (I(-1, -1) + 2 * I(-1, 0) + I(-1, 1));
	const int gy = (I(-1, 1) + 2 * I(0, 1) + I(1, 1)) - (I(-1, -1) + 2 * I(0, -1) + I(1, -1));
	return {gx / 8.0f, gy / 8.0f};
}

cv::Point2f gradientAt(const cv::Mat& img, cv::Point2f p)
{
	const int x0 = static_cast<int>(std::floor(p.x)), y0 = static_cast<int>(std::floor(p.y));
	const float ax = p.x - x0, ay = p.y - y0;
	return (1 - ax) * (1 - ay) * sobelGradient(img, x0, y0) + ax * (1 - ay) * sobelGradient(img, x0 + 1, y0) +
		(1 - ax) * ay * sobelGradient(img, x0, y0 + 1) + ax * ay * sobelGradient(img, x0 + 1, y0 + 1);
}
}  // namespace vlo::scale
