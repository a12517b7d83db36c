#include <opencv2/imgproc.hpp>
#include <vlo/vo/orb_extractor.h>

#include "feature_distribution.h"

#include <algorithm>
#include <cmath>

namespace vlo::vo
{
namespace
{
constexpr int kHalfPatch = 15;  // orientation patch radius (the 31 px ORB patch)

/// Intensity-centroid orientation in degrees on a circular patch (Rosin; ORB paper).
float centroidAngle(const cv::Mat& img, cv::Point2f pt, const std::vector<int>& umax)
{
	const uchar* c = &img.at<uchar>(cvRound(pt.y), cvRound(pt.x));
	const int step = static_cast<int>(img.step1());
	int m01 = 0, m10 = 0;
	for (int u = -kHalfPatch; u <= kHalfPatch; ++u) m10 += u * c[u];
	for (int v = 1; v <= kHalfPatch; ++v)
	{
		int vsum = 0;
		for (int u = -umax[v]; u <= umax[v]; ++u)
		{
			const int plus = c[u + v * step], minus = c[u - v * step];
			vsum += plus - minus;
			m10 += u * (plus + minus);
		}
		m01 += v * vsum;
	}
	return cv::fastAtan2(static_cast<float>(m01), static_cast<float>(m10));
}

}  // namespace

OrbExtractor::OrbExtractor(const OrbOptions& opt) : opt_(opt), pyramid_(opt.n_levels, opt.scale_factor)
{
	// Features per level in proportion to the level's area... as ORB-SLAM: a geometric series.
	const double f = 1.0 / opt.scale_factor;
	double n = opt.n_features * (1 - f) / (1 - std::pow(f, opt.n_levels));
	int sum = 0;
	per_level_.resize(opt.n_levels);
	for (int l = 0; l + 1 < opt.n_levels; ++l, n *= f)
	{
		per_level_[l] = static_cast<int>(std::lround(n));
		sum += per_level_[l];
	}
	per_level_.back() = std::max(opt.n_features - sum, 0);

	umax_.resize(kHalfPatch + 1);
	for (int v = 0; v <= kHalfPatch; ++v)
		umax_[v] = static_cast<int>(std::floor(std::sqrt(double(kHalfPatch * kHalfPatch - v * v)) + 0.5));

	orb_ = cv::ORB::create(opt.n_features, static_cast<float>(opt.scale_factor), opt.n_levels, opt.edge_threshold,
		0, 2, cv::ORB::FAST_SCORE, 31, opt.fast_threshold);
	orb_level_ = cv::ORB::create(opt.n_features, static_cast<float>(opt.scale_factor), 1, opt.edge_threshold, 0, 2,
		cv::ORB::FAST_SCORE, 31, opt.fast_threshold);
}

std::vector<cv::KeyPoint> OrbExtractor::detectSpread(const cv::Mat& im, int level) const
{
	const int border = opt_.edge_threshold - 3;  // FAST itself keeps 3 px off the ROI border
	const int w = im.cols - 2 * border, h = im.rows - 2 * border;
	const int want = per_level_[level];
	if (w < 16 || h < 16 || want <= 0) return {};
	// Weak corners only in cells without a strong one, then an even spread.
	const std::vector<cv::KeyPoint> kps = detail::detectFast(im(cv::Rect(border, border, w, h)), opt_.fallback_cell,
		opt_.fast_threshold, opt_.fast_min_threshold);
	std::vector<cv::KeyPoint> chosen = opt_.detector == "quadtree" ? detail::distributeQuadtree(kps, w, h, want)
																   : detail::distributeAnms(kps, w, h, want, opt_.anms_pool);
	for (auto& k : chosen)
	{
		k.pt += cv::Point2f(float(border), float(border));
		k.angle = centroidAngle(im, k.pt, umax_);
		k.octave = 0;  // the level's own image: what OpenCV's one-level ORB describes
		k.size = 31.f;
	}
	return chosen;
}

Features OrbExtractor::extract(const cv::Mat& gray) const
{
	CV_Assert(gray.type() == CV_8UC1);
	Features f;
	f.width = gray.cols;
	f.height = gray.rows;
	if (opt_.detector == "opencv")
		orb_->detectAndCompute(gray, cv::noArray(), f.keys, f.descriptors);
	else
	{
		std::vector<cv::Mat> levels(pyramid_.levels);
		levels[0] = gray;
		for (int l = 1; l < pyramid_.levels; ++l)
		{
			const cv::Size sz(static_cast<int>(std::lround(gray.cols * pyramid_.inv_scale[l])),
				static_cast<int>(std::lround(gray.rows * pyramid_.inv_scale[l])));
			cv::resize(levels[l - 1], levels[l], sz, 0, 0, cv::INTER_LINEAR);
		}
		// Per level: corners, then OpenCV's rBRIEF on that level's image (a one-level ORB; the
		// pyramid's own ORB would build a second pyramid), then level-0 coordinates.
		std::vector<cv::Mat> descriptors;
		for (int l = 0; l < pyramid_.levels; ++l)
		{
			std::vector<cv::KeyPoint> keys = detectSpread(levels[l], l);
			if (keys.empty()) continue;
			cv::Mat d;
			orb_level_->compute(levels[l], keys, d);  // keeps those edge_threshold off the border: all here
			const float s = static_cast<float>(pyramid_.scale[l]);
			for (auto& k : keys)
			{
				k.pt *= s;
				k.octave = l;
				k.size = 31.f * s;
				f.keys.push_back(k);
			}
			descriptors.push_back(d);
		}
		if (!descriptors.empty()) cv::vconcat(descriptors, f.descriptors);
	}
	if (f.descriptors.empty()) f.keys.clear();
	f.grid.build(f.keys, f.width, f.height);
	return f;
}
}  // namespace vlo::vo
