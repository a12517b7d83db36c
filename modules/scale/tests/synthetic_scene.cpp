#include "synthetic_scene.h"

#include <vlo/core/units.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace vlo::scale::test
{
namespace
{
/// Random rectangles of random grey: corners and edges at every scale from 10 cm to 1 m.
std::vector<cv::Mat> makeTexture(std::mt19937& rng)
{
	const int n = 512;
	cv::Mat t(n, n, CV_8U, cv::Scalar(128));
	std::uniform_int_distribution<int> pos(0, n - 1), size(3, 30), grey(25, 230);
	for (int k = 0; k < 1500; ++k)
	{
		const cv::Rect r(pos(rng), pos(rng), size(rng), size(rng));
		cv::rectangle(t, r, cv::Scalar(grey(rng)), cv::FILLED);
	}
	cv::Mat f;
	t.convertTo(f, CV_32F);
	// The texture tiles the plane: filter it with wrapped borders so that the seams stay invisible.
	const int pad = 8;
	cv::Mat w;
	cv::copyMakeBorder(f, w, pad, pad, pad, pad, cv::BORDER_WRAP);
	cv::GaussianBlur(w, w, cv::Size(0, 0), 0.8);
	std::vector<cv::Mat> mips{w(cv::Rect(pad, pad, n, n)).clone()};
	while (mips.back().cols > 8)
	{
		const int m = mips.back().cols;
		cv::copyMakeBorder(mips.back(), w, pad, pad, pad, pad, cv::BORDER_WRAP);
		cv::Mat d;
		cv::pyrDown(w, d);
		mips.push_back(d(cv::Rect(pad / 2, pad / 2, m / 2, m / 2)).clone());
	}
	return mips;
}

float sampleWrap(const cv::Mat& m, double x, double y)
{
	const int n = m.cols;
	const double fx = std::floor(x), fy = std::floor(y);
	const float ax = static_cast<float>(x - fx), ay = static_cast<float>(y - fy);
	auto wrap = [n](double v) { return static_cast<int>(((static_cast<long long>(v) % n) + n) % n); };
	const int x0 = wrap(fx), y0 = wrap(fy), x1 = (x0 + 1) % n, y1 = (y0 + 1) % n;
	return (1 - ax) * (1 - ay) * m.at<float>(y0, x0) + ax * (1 - ay) * m.at<float>(y0, x1) +
		(1 - ax) * ay * m.at<float>(y1, x0) + ax * ay * m.at<float>(y1, x1);
}

TexturedPlane plane(Eigen::Vector3d o, Eigen::Vector3d u, Eigen::Vector3d v, double w, double h, int tex)
{
	return {o, u.normalized(), v.normalized(), w, h, tex, 0.03};
}
}  // namespace

bool Scene::intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& dir, double& t, int& hit) const
{
	hit = -1;
	t = std::numeric_limits<double>::infinity();
	for (size_t i = 0; i < planes.size(); ++i)
	{
		const TexturedPlane& p = planes[i];
		const Eigen::Vector3d n = p.u.cross(p.v);
		const double den = n.dot(dir);
		if (std::abs(den) < 1e-12) continue;
		const double ti = n.dot(p.origin - o) / den;
		if (!(ti > 1e-6 && ti < t)) continue;
		const Eigen::Vector3d q = o + ti * dir - p.origin;
		const double a = q.dot(p.u), b = q.dot(p.v);
		if (a < 0 || a > p.width || b < 0 || b > p.height) continue;
		t = ti, hit = static_cast<int>(i);
	}
	return hit >= 0;
}

float Scene::shade(int i, const Eigen::Vector3d& X, double footprint) const
{
	const TexturedPlane& p = planes[i];
	const auto& m = mips[p.texture];
	// Trilinear mip-mapping: no aliasing that would crawl differently in the two images.
	const double level = std::clamp(std::log2(std::max(footprint / p.texel, 1.0)), 0.0, m.size() - 1.001);
	const int l0 = static_cast<int>(level);
	const double f = level - l0;
	const Eigen::Vector3d q = X - p.origin;
	auto at = [&](int l) {
		const double s = p.texel * std::ldexp(1.0, l);
		return sampleWrap(m[l], q.dot(p.u) / s, q.dot(p.v) / s);
	};
	return static_cast<float>((1 - f) * at(l0) + f * at(l0 + 1));
}

Scene streetScene(std::uint32_t seed)
{
	Scene s;
	const Eigen::Vector3d X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
	const double g = -1.73;  // ground height in the vehicle (LiDAR) frame
	s.planes = {plane({-20, -12, g}, X, Y, 160, 24, 0),  // ground
		plane({-20, 7, g}, X, Z, 160, 14, 1),  // left facade
		plane({-20, -7, g}, X, Z, 160, 14, 2),  // right facade
		plane({70, -12, g}, Y, Z, 24, 14, 3),  // end wall
		plane({12, 1.5, g}, Y, Z, 2.5, 2.0, 4),  // panels across the street
		plane({20, -4.5, g}, Y, Z, 3.0, 2.5, 5),  //
		plane({35, -1.0, g}, Y, Z, 2.0, 3.0, 6),  //
		plane({8, -3.5, g}, X, Z, 5.0, 1.5, 7),  // a panel along the street
		plane({15, 5.0, g}, Y, Z, 0.3, 6.0, 8)};  // a pole
	std::mt19937 rng(seed);
	for (size_t i = 0; i < s.planes.size(); ++i) s.mips.push_back(makeTexture(rng));
	return s;
}

LidarModel hdl64()
{
	LidarModel m;
	for (int k = 0; k < 64; ++k) m.elevations_deg.push_back(2.0 - k * (26.9 / 63));
	m.azimuth_step_deg = 0.17;
	return m;
}

LidarModel vlp16()
{
	LidarModel m;
	for (int k = 0; k < 16; ++k) m.elevations_deg.push_back(-15.0 + 2.0 * k);
	m.azimuth_step_deg = 0.2;
	return m;
}

SensorRig kittiRig()
{
	SensorRig r;
	r.has_camera = r.has_lidar = true;
	r.camera = {718.856, 718.856, 607.1928, 185.2157, 1241, 376};
	Eigen::Matrix3d R;  // optical axes (x right, y down, z forward) in the vehicle frame
	R.col(0) = Eigen::Vector3d(0, -1, 0), R.col(1) = Eigen::Vector3d(0, 0, -1), R.col(2) = Eigen::Vector3d(1, 0, 0);
	r.vehicle_T_camera.linear() = R;
	r.vehicle_T_camera.translation() = Eigen::Vector3d(0.27, 0, -0.08);
	return r;
}

cv::Mat renderImage(const Scene& scene, const PinholeCamera& cam, const Eigen::Isometry3d& world_T_camera,
	double noise_sigma, std::uint32_t seed)
{
	cv::Mat f(cam.height, cam.width, CV_32F, cv::Scalar(200));  // sky
	const Eigen::Matrix3d R = world_T_camera.linear();
	const Eigen::Vector3d o = world_T_camera.translation();
	for (int y = 0; y < cam.height; ++y)
		for (int x = 0; x < cam.width; ++x)
		{
			const Eigen::Vector3d rc((x - cam.cx) / cam.fx, (y - cam.cy) / cam.fy, 1.0);
			const Eigen::Vector3d d = (R * rc).normalized();
			double t;
			int p;
			if (!scene.intersect(o, d, t, p)) continue;
			const TexturedPlane& pl = scene.planes[p];
			const double cosInc = std::max(std::abs(pl.u.cross(pl.v).dot(d)), 0.05);
			// A pixel at angle a off the axis spans t cos^2(a) / f metres across the ray; a slanted
			// surface stretches that by 1 / cos(incidence).
			const double c = rc.normalized().z();
			f.at<float>(y, x) = scene.shade(p, o + t * d, t * c * c / cam.fx / cosInc);
		}
	if (noise_sigma > 0)
	{
		cv::Mat n(f.size(), CV_32F);
		cv::RNG rng(seed);
		rng.fill(n, cv::RNG::NORMAL, 0.0, noise_sigma);
		f += n;
	}
	cv::Mat out;
	f.convertTo(out, CV_8U);
	return out;
}

PointCloud scanScene(const Scene& scene, const LidarModel& m, const Eigen::Isometry3d& world_T_lidar, std::uint32_t seed)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> noise(0.0, m.range_noise);
	PointCloud out;
	const int steps = static_cast<int>(std::lround(360.0 / m.azimuth_step_deg));
	for (int a = 0; a < steps; ++a)
		for (double e : m.elevations_deg)
		{
			const double az = a * m.azimuth_step_deg * kRadPerDeg, el = e * kRadPerDeg;
			const Eigen::Vector3d dl(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
			double t;
			int p;
			if (!scene.intersect(world_T_lidar.translation(), world_T_lidar.linear() * dl, t, p) || t > m.max_range)
				continue;
			const Eigen::Vector3d q = dl * (t + (m.range_noise > 0 ? noise(rng) : 0.0));
			out.push_back({static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()), 0.5f});
		}
	return out;
}

FramePair makePair(const Scene& scene, const LidarModel& lidar, double forward, double yaw_deg, double image_noise,
	std::uint32_t seed)
{
	FramePair f;
	f.rig = kittiRig();
	const Eigen::Isometry3d w_T_v0 = Eigen::Isometry3d::Identity();
	Eigen::Isometry3d w_T_v1 = Eigen::Isometry3d::Identity();
	w_T_v1.translate(Eigen::Vector3d(forward, 0.03 * forward, 0.0));
	w_T_v1.rotate(Eigen::AngleAxisd(yaw_deg * kRadPerDeg, Eigen::Vector3d::UnitZ()));
	const Eigen::Isometry3d w_T_c0 = w_T_v0 * f.rig.vehicle_T_camera, w_T_c1 = w_T_v1 * f.rig.vehicle_T_camera;
	f.prev = renderImage(scene, f.rig.camera, w_T_c0, image_noise, seed);
	f.cur = renderImage(scene, f.rig.camera, w_T_c1, image_noise, seed + 1);
	f.scan = scanScene(scene, lidar, w_T_v0 * f.rig.vehicle_T_lidar, seed + 2);
	f.cur_T_prev = w_T_c1.inverse() * w_T_c0;
	return f;
}

Eigen::Isometry3d withScaledTranslation(const Eigen::Isometry3d& T, double k)
{
	Eigen::Isometry3d out = T;
	out.translation() *= k;
	return out;
}
}  // namespace vlo::scale::test
