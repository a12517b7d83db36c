#include "synthetic.h"

#include <opencv2/core.hpp>

#include <cmath>
#include <random>

namespace vlo::viz::synth
{
namespace
{
struct Box
{
	Eigen::Vector3d lo, hi;
	int tex;  ///< 0 building, 1 car, 2 pole
};
// A street in the vehicle frame (x forward, y left, z up, origin on the road).
const Box kBoxes[] = {{{6, 8, 0}, {38, 20, 0}, 0}, {{42, 9, 0}, {70, 22, 0}, 0}, {{-5, -20, 0}, {24, -9, 0}, 0},
	{{28, -22, 0}, {62, -10, 0}, 0}, {{85, -40, 0}, {88, 40, 0}, 0}, {{12, 3.2, 0}, {16.5, 5, 0}, 1},
	{{21, -5.6, 0}, {25.4, -3.8, 0}, 1}, {{33, 3.4, 0}, {37.5, 5.2, 0}, 1}, {{9, -7.3, 0}, {9.3, -7, 0}, 2},
	{{30, 7.0, 0}, {30.3, 7.3, 0}, 2}};
const double kTop[] = {14, 9, 11, 18, 12, 1.5, 1.4, 1.6, 7, 7};

struct Hit
{
	double t = INFINITY;
	int box = -1;  ///< -1 ground
	Eigen::Vector3d p, n;
};

Hit cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d)
{
	Hit h;
	if (d.z() < 0) h.t = -o.z() / d.z(), h.n = Eigen::Vector3d::UnitZ();
	for (int b = 0; b < int(std::size(kBoxes)); ++b)
	{
		Eigen::Vector3d lo = kBoxes[b].lo, hi = kBoxes[b].hi;
		hi.z() = kTop[b];
		double t0 = 0, t1 = INFINITY;
		int axis = -1;
		for (int a = 0; a < 3; ++a)
		{
			double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
			if (ta > tb) std::swap(ta, tb);
			if (ta > t0) t0 = ta, axis = a;
			t1 = std::min(t1, tb);
		}
		if (t0 <= t1 && axis >= 0 && t0 < h.t)
		{
			h.t = t0, h.box = b;
			h.n = Eigen::Vector3d::Zero();
			h.n[axis] = d[axis] > 0 ? -1 : 1;
		}
	}
	if (std::isfinite(h.t)) h.p = o + h.t * d;
	return h;
}

double hash(int a, int b) { return std::fmod(std::abs(std::sin(a * 12.9898 + b * 78.233) * 43758.5453), 1.0); }

double shade(const Hit& h)
{
	if (h.box < 0)  // asphalt, dashed centre line, kerbs and sidewalk slabs
	{
		const double x = h.p.x(), y = h.p.y();
		if (std::abs(y) > 7.5)
			return 150 + 30 * hash(int(std::floor(x / 1.5)), int(std::floor(y / 1.5))) -
				40 * (std::fmod(std::abs(x), 1.5) < 0.05);
		if (std::abs(y) < 0.08 && std::fmod(std::abs(x), 6) < 3) return 225;
		return 80 + 25 * hash(int(std::floor(x * 8)), int(std::floor(y * 8)));
	}
	const double light = h.n.z() > 0.5 ? 1.15 : std::abs(h.n.x()) > 0.5 ? 0.85
																		: 1.0;
	const double a = std::abs(h.n.x()) > 0.5 ? h.p.y() : h.p.x(), z = h.p.z();
	const int tex = kBoxes[h.box].tex;
	if (tex == 1) return light * (z > 0.9 ? 45 : 110 + 40 * (h.box % 2));
	if (tex == 2) return light * 60;
	const double fa = std::fmod(std::abs(a), 2.5), fz = std::fmod(z, 3.0);
	const bool window = fa > 0.6 && fa < 1.9 && fz > 0.8 && fz < 2.3 && z > 1;
	return light * (window ? 40 + 30 * hash(int(a / 2.5), int(z / 3)) : 150 + 12 * (h.box % 3));
}
}  // namespace

SensorRig kittiLikeRig()
{
	SensorRig rig;
	rig.has_camera = rig.has_lidar = true;
	rig.camera = {718.856, 718.856, 607.1928, 185.2157, 1241, 376};
	rig.vehicle_T_camera.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // columns: x right, y down, z forward
	rig.vehicle_T_camera.translation() = Eigen::Vector3d(0.27, 0, 1.65);
	rig.vehicle_T_lidar.translation() = Eigen::Vector3d(0, 0, 1.73);
	return rig;
}

CameraLidarFrame streetFrame(unsigned seed)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> n(0, 1);
	CameraLidarFrame f;
	f.rig = kittiLikeRig();
	const PinholeCamera& c = f.rig.camera;
	cv::Mat img(c.height, c.width, CV_8UC1);
	const Eigen::Vector3d co = f.rig.vehicle_T_camera.translation();
	const Eigen::Matrix3d R = f.rig.vehicle_T_camera.linear();
	for (int v = 0; v < c.height; ++v)
		for (int u = 0; u < c.width; ++u)
		{
			const Hit h = cast(co, R * Eigen::Vector3d((u - c.cx) / c.fx, (v - c.cy) / c.fy, 1));
			const double g = std::isfinite(h.t) && h.t < 300 ? shade(h) : 215 - 0.2 * v;  // sky
			img.at<std::uint8_t>(v, u) = cv::saturate_cast<std::uint8_t>(g + 3 * n(rng));
		}
	f.image = mrpt::img::CImage(img, mrpt::img::DEEP_COPY);
	const Eigen::Vector3d lo = f.rig.vehicle_T_lidar.translation();
	for (int b = 0; b < 64; ++b)  // HDL-64E: +2 to -24.8 degrees, 0.2 degree azimuth steps
	{
		const double el = (2 - 26.8 * b / 63) * M_PI / 180;
		for (int a = 0; a < 1800; ++a)
		{
			const double az = a * 0.2 * M_PI / 180;
			const Eigen::Vector3d d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
			const Hit h = cast(lo, d);
			if (!(h.t < 120)) continue;
			const Eigen::Vector3d p = (h.t + 0.01 * n(rng)) * d;
			f.scan.push_back({float(p.x()), float(p.y()), float(p.z()), float(shade(h) / 255)});
		}
	}
	return f;
}
}  // namespace vlo::viz::synth
