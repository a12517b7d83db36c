#include <vlo/scale/epipolar.h>
#include <vlo/scale/keypoint_tests.h>
#include <vlo/scale/selection.h>

#include <algorithm>
#include <cmath>

namespace vlo::scale
{
bool cornerTest(const cv::Mat& img, int x, int y, const ScaleOptions& opt)
{
	switch (opt.keypoint_test)
	{
		case KeypointTest::Fast9: return fast9(img, x, y, opt.fast_threshold);
		case KeypointTest::Fast12Pretest:
			return fast12Pretest(img, x, y, opt.fast_threshold, opt.fast12_min_count, opt.fast12_same_sign);
		case KeypointTest::None: return true;
	}
	return false;
}

std::vector<Keypoint> selectKeypoints(const cv::Mat& img, const std::vector<DepthPixel>& projected,
	const ScaleOptions& opt, SelectionCounts* counts, const Eigen::Vector3d* epipole)
{
	const bool preselect = epipole && opt.preselect_min_abs_cos > 0 && epipole->squaredNorm() > 0;
	const int cell = opt.nms_cell;
	const int gw = (img.cols + cell - 1) / cell, gh = (img.rows + cell - 1) / cell;
	std::vector<Keypoint> best(static_cast<size_t>(gw) * gh);
	SelectionCounts n;
	const float g2min = static_cast<float>(opt.gradient_threshold * opt.gradient_threshold);
	for (size_t i = 0; i < projected.size(); ++i)
	{
		const int x = static_cast<int>(std::lround(projected[i].px.x));
		const int y = static_cast<int>(std::lround(projected[i].px.y));
		if (x < 3 || y < 3 || x > img.cols - 4 || y > img.rows - 4) continue;
		if (!cornerTest(img, x, y, opt)) continue;
		++n.corner;
		const cv::Point2f g = sobelGradient(img, x, y);
		const float g2 = g.dot(g);
		if (g2 <= g2min) continue;
		++n.gradient;
		if (preselect)
		{
			const Eigen::Vector3d line = epipole->cross(Eigen::Vector3d(projected[i].px.x, projected[i].px.y, 1.0));
			if (!(absCosToLine(line, g) > opt.preselect_min_abs_cos)) continue;
		}
		++n.direction;
		Keypoint& b = best[static_cast<size_t>(y / cell) * gw + x / cell];
		// Scan order decides ties, so the result does not depend on anything but the input.
		if (b.projected < 0 || g2 > b.score) b = {static_cast<int>(i), g2};
	}
	if (counts) *counts = n;

	std::vector<Keypoint> out;
	for (const auto& b : best)
		if (b.projected >= 0) out.push_back({b.projected, std::sqrt(b.score)});
	std::sort(out.begin(), out.end(), [](const Keypoint& a, const Keypoint& b) {
		return a.score != b.score ? a.score > b.score : a.projected < b.projected;
	});
	if (out.size() > static_cast<size_t>(opt.max_keypoints)) out.resize(opt.max_keypoints);
	return out;
}
}  // namespace vlo::scale
