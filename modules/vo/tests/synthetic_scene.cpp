#include "synthetic_scene.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace vlo::vo::test
{
namespace
{
cv::Mat makeTexture(unsigned seed)
{
	constexpr int N = 1024;
	cv::Mat t(N, N, CV_8U, cv::Scalar(128));
	std::mt19937 rng(seed);
	std::uniform_int_distribution<int> pos(0, N - 1), gray(20, 235), size(3, 28);
	for (int i = 0; i < 2500; ++i)
	{
		const cv::Point c(pos(rng), pos(rng));
		const int s = size(rng), g = gray(rng);
		if (i % 2)
			cv::circle(t, c, s / 2, cv::Scalar(g), cv::FILLED, cv::LINE_AA);
		else
			cv::rectangle(t, cv::Rect(c.x, c.y, s, s * (1 + i % 3) / 2), cv::Scalar(g), cv::FILLED);
	}
	cv::Mat f;
	t.convertTo(f, CV_32F);
	cv::GaussianBlur(f, f, cv::Size(3, 3), 0.8);
	return f;
}
}  // namespace

StreetRenderer::StreetRenderer(const StreetScene& scene, const PinholeCamera& cam) : scene_(scene), cam_(cam)
{
	mip_.push_back(makeTexture(scene.seed));
	while (mip_.back().cols > 8)
	{
		cv::Mat d;
		cv::pyrDown(mip_.back(), d);
		mip_.push_back(d);
	}
}

double StreetRenderer::sample(int plane, double a, double b, double footprint) const
{
	const double level = std::clamp(std::log2(std::max(footprint / texel_, 1.0)), 0.0, double(mip_.size() - 1));
	const cv::Mat& m = mip_[static_cast<std::size_t>(std::lround(level))];
	const double scale = m.cols / (1024.0 * texel_);
	// Each plane reads the texture with its own offset so that they do not repeat each other.
	double u = (a + 37.0 * plane) * scale, v = (b + 53.0 * plane) * scale;
	const int n = m.cols;
	u -= std::floor(u / n) * n;
	v -= std::floor(v / n) * n;
	const int u0 = static_cast<int>(u), v0 = static_cast<int>(v);
	const double fu = u - u0, fv = v - v0;
	auto at = [&](int r, int c) { return m.at<float>(r % n, c % n); };
	return (1 - fv) * ((1 - fu) * at(v0, u0) + fu * at(v0, u0 + 1)) + fv * ((1 - fu) * at(v0 + 1, u0) + fu * at(v0 + 1, u0 + 1));
}

cv::Mat StreetRenderer::render(const Eigen::Isometry3d& T) const
{
	cv::Mat img(cam_.height, cam_.width, CV_8U);
	const Eigen::Matrix3d R = T.linear();
	const Eigen::Vector3d o = T.translation();
	for (int r = 0; r < cam_.height; ++r)
	{
		auto* row = img.ptr<uint8_t>(r);
		for (int c = 0; c < cam_.width; ++c)
		{
			const Eigen::Vector3d d = R * Eigen::Vector3d((c - cam_.cx) / cam_.fx, (r - cam_.cy) / cam_.fy, 1.0).normalized();
			double best = scene_.far;
			int plane = -1;
			auto hit = [&](double t, int p) {
				if (t > 0.1 && t < best) best = t, plane = p;
			};
			if (d.y() > 1e-9) hit((scene_.camera_height - o.y()) / d.y(), 0);
			if (d.x() < -1e-9) hit((-scene_.half_width - o.x()) / d.x(), 1);
			if (d.x() > 1e-9) hit((scene_.half_width - o.x()) / d.x(), 2);
			double g = 200;  // sky
			if (plane >= 0)
			{
				const Eigen::Vector3d p = o + best * d;
				const double cos_inc = plane == 0 ? std::abs(d.y()) : std::abs(d.x());
				const double footprint = best / cam_.fx / std::max(cos_inc, 0.05);
				g = plane == 0 ? sample(0, p.x(), p.z(), footprint) : sample(plane, p.z(), p.y(), footprint);
			}
			row[c] = static_cast<uint8_t>(std::clamp(std::lround(g), 0L, 255L));
		}
	}
	return img;
}

PinholeCamera kittiCamera(double scale)
{
	PinholeCamera c;
	c.fx = c.fy = 718.856 * scale;
	c.cx = 607.1928 * scale;
	c.cy = 185.2157 * scale;
	c.width = static_cast<int>(std::lround(1241 * scale));
	c.height = static_cast<int>(std::lround(376 * scale));
	return c;
}

Eigen::Isometry3d drivePose(int k, double speed)
{
	const double s = k * speed;
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	const double yaw = 0.06 * std::sin(s / 9.0);  // about the vertical (y) axis
	T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix() *
		Eigen::AngleAxisd(0.01 * std::sin(s / 5.0), Eigen::Vector3d::UnitX()).toRotationMatrix();
	T.translation() = Eigen::Vector3d(1.5 * std::sin(s / 14.0), 0.03 * std::sin(s / 3.0), s);
	return T;
}
}  // namespace vlo::vo::test
