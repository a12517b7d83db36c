#include <vlo/scale/tracking.h>

#include <opencv2/video/tracking.hpp>

#include <algorithm>
#include <cmath>

namespace vlo::scale
{
namespace
{
std::vector<cv::Point2f> warp(const cv::Matx33d& H, const std::vector<cv::Point2f>& pts)
{
	std::vector<cv::Point2f> out;
	out.reserve(pts.size());
	for (const auto& p : pts)
	{
		const cv::Vec3d q = H * cv::Vec3d(p.x, p.y, 1.0);
		out.emplace_back(static_cast<float>(q[0] / q[2]), static_cast<float>(q[1] / q[2]));
	}
	return out;
}
}  // namespace

LkPyramid buildLkPyramid(const cv::Mat& grey, const ScaleOptions& opt)
{
	LkPyramid p;
	// A copy of the image, never a view of it: a pyramid may outlive the frame it was built from.
	p.max_level = cv::buildOpticalFlowPyramid(grey, p.levels, cv::Size(opt.lk_window, opt.lk_window), opt.lk_levels, true,
		cv::BORDER_REFLECT_101, cv::BORDER_CONSTANT, false);
	return p;
}

std::vector<Track> trackPoints(const cv::Mat& prev, const cv::Mat& cur, const std::vector<cv::Point2f>& pts,
	const ScaleOptions& opt, const cv::Matx33d& H)
{
	if (pts.empty()) return {};
	return trackPoints(buildLkPyramid(prev, opt), buildLkPyramid(cur, opt), cur.size(), pts, opt, H);
}

std::vector<Track> trackPoints(const LkPyramid& pyrPrev, const LkPyramid& pyrCur, cv::Size size,
	const std::vector<cv::Point2f>& pts, const ScaleOptions& opt, const cv::Matx33d& H)
{
	std::vector<Track> out(pts.size());
	if (pts.empty()) return out;
	const cv::Size win(opt.lk_window, opt.lk_window);
	const cv::TermCriteria term(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, opt.lk_iterations, opt.lk_epsilon);
	const int levels = std::min(pyrPrev.max_level, pyrCur.max_level);

	const bool prior = H != cv::Matx33d::zeros();
	const int flags = prior ? cv::OPTFLOW_USE_INITIAL_FLOW : 0;
	std::vector<cv::Point2f> fwd = prior ? warp(H, pts) : std::vector<cv::Point2f>{};
	std::vector<uchar> st;
	std::vector<float> err;
	cv::calcOpticalFlowPyrLK(pyrPrev.levels, pyrCur.levels, pts, fwd, st, err, win, levels, term, flags);

	std::vector<uchar> stBack(pts.size(), 1);
	std::vector<cv::Point2f> back;
	if (opt.lk_forward_backward)
	{
		if (prior) back = warp(H.inv(), fwd);
		cv::calcOpticalFlowPyrLK(pyrCur.levels, pyrPrev.levels, fwd, back, stBack, err, win, levels, term, flags);
	}

	const float xmax = static_cast<float>(size.width - 3), ymax = static_cast<float>(size.height - 3);
	for (size_t i = 0; i < pts.size(); ++i)
	{
		Track& t = out[i];
		t.cur = fwd[i];
		if (!st[i] || !std::isfinite(t.cur.x) || !std::isfinite(t.cur.y)) continue;  // Lost
		if (t.cur.x < 2 || t.cur.y < 2 || t.cur.x > xmax || t.cur.y > ymax)
		{
			t.status = TrackStatus::OutOfImage;
			continue;
		}
		if (opt.lk_forward_backward)
		{
			if (!stBack[i]) continue;
			const cv::Point2f d = back[i] - pts[i];
			t.fb_error = std::sqrt(d.dot(d));
			if (!(t.fb_error <= opt.lk_fb_max_error))
			{
				t.status = TrackStatus::ForwardBackward;
				continue;
			}
		}
		t.status = TrackStatus::Ok;
	}
	return out;
}
}  // namespace vlo::scale
