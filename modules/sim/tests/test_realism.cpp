// The realistic sensor (realism.h): each error has the documented size, is fixed by the seed, and a
// realistic scan of exact geometry deviates from it by exactly the modelled errors.
#include <gtest/gtest.h>
#include <vlo/core/units.h>
#include <vlo/sim/camera_errors.h>
#include <vlo/sim/config.h>
#include <vlo/sim/lidar_errors.h>
#include <vlo/sim/lidar_sim.h>
#include <vlo/sim/renderer.h>
#include <vlo/sim/rng.h>
#include <vlo/sim/world.h>

#include <mrpt/opengl/COpenGLScene.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace vlo;
using namespace vlo::sim;

namespace
{
struct Stats
{
	double mean = 0, sd = 0;
};

Stats stats(const std::vector<double>& v)
{
	Stats s;
	for (double x : v) s.mean += x;
	s.mean /= static_cast<double>(v.size());
	for (double x : v) s.sd += (x - s.mean) * (x - s.mean);
	s.sd = std::sqrt(s.sd / static_cast<double>(v.size()));
	return s;
}

double median(std::vector<double> v)
{
	std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
	return v[v.size() / 2];
}

/// Ranges measured by laser 0 of `errors` for `n` echoes `e`, without its fixed range offset.
std::vector<double> measured(const LidarErrors& errors, const Echo& e, int n, std::size_t* lost = nullptr)
{
	Rng rng(3);
	std::vector<double> out;
	for (int i = 0; i < n; ++i)
	{
		double r = 0;
		float intensity = 0;
		if (errors.measure(0, e, rng, r, intensity)) out.push_back(r - errors.rangeOffset(0));
		else if (lost)
			++*lost;
	}
	return out;
}
}  // namespace

TEST(LidarErrors, CalibrationErrorsHaveTheDocumentedSpreadAndAreFixedBySeed)
{
	const LidarRealism p = realisticSensors(hdl64()).lidar;
	const int lasers = 4000;  // many lasers, to measure the spread to a few percent
	const LidarErrors a(p, lasers, 7), b(p, lasers, 7), c(p, lasers, 8);
	std::vector<double> el, az, dr;
	for (int i = 0; i < lasers; ++i)
	{
		el.push_back(a.elevationOffset(i)), az.push_back(a.azimuthOffset(i)), dr.push_back(a.rangeOffset(i));
		EXPECT_EQ(a.elevationOffset(i), b.elevationOffset(i));
		EXPECT_EQ(a.rangeOffset(i), b.rangeOffset(i));
	}
	EXPECT_NEAR(stats(el).sd, 0.06 * kRadPerDeg, 0.004 * kRadPerDeg);
	EXPECT_NEAR(stats(az).sd, 0.06 * kRadPerDeg, 0.004 * kRadPerDeg);
	EXPECT_NEAR(stats(dr).sd, 0.015, 0.001);
	EXPECT_NE(a.elevationOffset(0), c.elevationOffset(0)) << "another seed, another unit";
}

TEST(LidarErrors, RangeNoiseHasTheDocumentedSigmaGrowingWithRangeAndIncidence)
{
	const LidarErrors hdl(realisticSensors(hdl64()).lidar, 64, 1);
	// A bright wall faced squarely at 10 m: 2 cm (HDL-64E S2) times 1 + (10 / R_max)^2, R_max = 50 sqrt(8) m.
	const double rmax = 50 * std::sqrt(8.0);
	EXPECT_NEAR(hdl.detectionRange(255, 1.0), rmax, 1e-9);
	EXPECT_NEAR(hdl.detectionRange(0, 1.0), 50 * std::sqrt(0.5), 1e-9);  // 5 %: a black surface
	const double square = 0.02 * (1 + std::pow(10 / rmax, 2));
	const Stats s = stats(measured(hdl, {10, 1.0, 0, 255}, 40000));
	EXPECT_NEAR(s.mean, 10, 0.0005);
	EXPECT_NEAR(s.sd, square, 0.02 * square);
	// The same surface at 40 m and 80 deg incidence: the footprint's spread, 40 * 1 mrad * tan(80 deg) / sqrt 3.
	const double c80 = std::cos(80 * kRadPerDeg), r80 = hdl.detectionRange(255, c80);
	const double grazing = std::hypot(0.02 * (1 + std::pow(40 / r80, 2)), 40 * 0.001 * std::tan(80 * kRadPerDeg) / std::sqrt(3.0));
	EXPECT_NEAR(hdl.rangeSigma(40, c80, r80), grazing, 1e-12);
	EXPECT_GT(grazing, 6 * square);
	const Stats g = stats(measured(hdl, {40, c80, 0, 255}, 40000));
	EXPECT_NEAR(g.sd, grazing, 0.03 * grazing);
	// VLP-16: +-3 cm.
	const LidarErrors vlp(realisticSensors(vlp16()).lidar, 16, 1);
	EXPECT_NEAR(stats(measured(vlp, {10, 1.0, 0, 255}, 40000)).sd, 0.03 * (1 + std::pow(10 / rmax, 2)), 0.0006);
}

TEST(LidarErrors, DarkAndGrazingSurfacesLoseTheirEchoes)
{
	const LidarErrors e(realisticSensors(hdl64()).lidar, 64, 1);
	const auto kept = [&](const Echo& echo) {
		std::size_t lost = 0;
		const auto n = measured(e, echo, 20000, &lost).size();
		return static_cast<double>(n) / static_cast<double>(n + lost);
	};
	EXPECT_NEAR(kept({20, 1.0, 0, 200}), 0.995, 0.002);  // only the 0.5 % lost regardless
	EXPECT_LT(kept({60, 1.0, 0, 0}), 0.01);  // black beyond its 35 m
	EXPECT_NEAR(kept({50 * std::sqrt(0.5), 1.0, 0, 0}), 0.5 * 0.995, 0.015);  // half at the detection range
	// Grey asphalt (rho 0.285) at 87 deg incidence, the road 33 m ahead seen from 1.73 m: R_max 40 m.
	const uint8_t asphalt = 80;
	const double c = std::cos(87 * kRadPerDeg), rmax = e.detectionRange(asphalt, c);
	EXPECT_NEAR(rmax, 50 * std::sqrt(0.285 * std::sqrt(c) / 0.1), 0.1);
	EXPECT_NEAR(rmax, 40.4, 0.1);
	EXPECT_GT(kept({0.7 * rmax, c, 0, asphalt}), 0.97);
	EXPECT_LT(kept({1.3 * rmax, c, 0, asphalt}), 0.03);
	EXPECT_GT(e.detectionRange(asphalt, 1.0), 2 * rmax) << "the same asphalt faced squarely";
}

TEST(LidarErrors, MixedReturnsLieBetweenTheTwoSurfaces)
{
	LidarRealism p = realisticSensors(hdl64()).lidar;
	p.base_sigma = 1e-6;  // see the mixing alone
	p.range_offset_m = 0;
	const LidarErrors e(p, 64, 1);
	const std::vector<double> r = measured(e, {10, 1.0, 11.5, 255}, 20000);  // a wall 1.5 m behind the edge
	const auto between = std::count_if(r.begin(), r.end(), [](double x) { return x > 10.001 && x < 11.5; });
	EXPECT_NEAR(static_cast<double>(between) / static_cast<double>(r.size()), 0.5, 0.02);
	EXPECT_TRUE(std::all_of(r.begin(), r.end(), [](double x) { return x > 9.999 && x < 11.5; }));
	// Surfaces farther apart than 3 m are told apart: no mixing.
	const std::vector<double> far = measured(e, {10, 1.0, 14, 255}, 2000);
	EXPECT_TRUE(std::all_of(far.begin(), far.end(), [](double x) { return std::abs(x - 10) < 0.001; }));
}

TEST(LidarErrors, RawSweepCarriesNoPointTimes)
{
	PointCloud cloud;
	cloud.has_time = cloud.has_ring = true;
	cloud.push_back({1, 2, 3, 204, -0.03f, 7});
	dropPointTimes(cloud);
	EXPECT_FALSE(cloud.has_time || cloud.has_ring);
	EXPECT_EQ(cloud[0].time, 0.0f);
	EXPECT_EQ(cloud[0].ring, 0);
	EXPECT_FLOAT_EQ(cloud[0].intensity, 0.8f);  // 8-bit reflectivity back to 0..1
}

/// Ground z = 0 and a wall x = 12 in one uniform grey, unshaded: every echo's reflectivity is known.
World uniformWorld()
{
	World w;
	Texture t;
	t.image = mrpt::img::CImage(16, 16, mrpt::img::CH_GRAY);
	t.image.asCvMatRef().setTo(200);
	const int id = w.addTexture(t, false);
	w.addMetricQuad(id, {-150, -150, 0}, {150, -150, 0}, {150, 150, 0}, {-150, 150, 0});
	w.addMetricQuad(id, {12, 60, 0}, {12, -60, 0}, {12, -60, 10}, {12, 60, 10});
	return w;
}

TEST(LidarRealism, ScanOfExactGeometryDeviatesByTheModelledErrorsAlone)
{
	// Every point is the measured range along the laser's nominal direction; the truth is the exact hit
	// along the direction it really fired (nominal + its calibration offsets). The difference, less the
	// laser's range offset, over the modelled sigma at that range and incidence, is N(0, 1) but for the
	// mixed returns at the wall's edges.
	const World w = uniformWorld();
	const LidarModel model = hdl64();
	const LidarSim lidar(model, false);
	const LidarErrors errors(realisticSensors(model).lidar, 64, 11);
	mrpt::opengl::COpenGLScene scene;
	scene.insert(w.makeOpenGL());
	Renderer renderer(std::vector<std::pair<int, int>>(lidar.viewCount(), lidar.tileSize()));
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
	pose.translation() = Eigen::Vector3d(0, 0, 1.73);
	const LidarSim::PoseAt at = [&](double) { return pose; };
	const auto views = lidar.views(at);
	std::vector<RenderedView> tiles;
	renderer.render(scene, views, tiles, true);
	Rng rng(2);
	const PointCloud cloud = lidar.sample(tiles, views, at, w.foliage(), {0, 0, 0, &errors}, rng);
	ASSERT_GT(cloud.size(), 60000u);
	std::vector<double> z, calibration;
	for (const auto& p : cloud)
	{
		const Eigen::Vector3d q(p.x, p.y, p.z);
		const int laser = 63 - p.ring;  // hdl64's elevations run top to bottom
		const double el = model.elevations_deg[static_cast<std::size_t>(laser)] * kRadPerDeg + errors.elevationOffset(laser);
		const double phi = std::atan2(q.y(), q.x()) + errors.azimuthOffset(laser);
		const Eigen::Vector3d fired(std::cos(el) * std::cos(phi), std::cos(el) * std::sin(phi), std::sin(el));
		double truth = 0;
		ASSERT_TRUE(w.raycast(pose.translation(), fired, 200, truth));
		const Eigen::Vector3d hit = pose.translation() + truth * fired;
		const Eigen::Vector3d normal = std::abs(hit.z()) < 1e-4 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
		const double c = std::abs(normal.dot(fired));
		const double sigma = errors.rangeSigma(truth, c, errors.detectionRange(200, c));
		z.push_back((q.norm() - errors.rangeOffset(laser) - truth) / sigma);
		// What the calibration errors alone do to the point: off the nominal direction's hit.
		double nominal = 0;
		if (w.raycast(pose.translation(), q.normalized(), 200, nominal)) calibration.push_back(std::abs(truth - nominal));
	}
	std::vector<double> absz;
	for (double v : z) absz.push_back(std::abs(v));
	EXPECT_NEAR(1.4826 * median(absz), 1.0, 0.03) << "robust sigma of the normalised range error";
	const auto outliers = std::count_if(absz.begin(), absz.end(), [](double v) { return v > 6; });
	EXPECT_LT(outliers, static_cast<long>(cloud.size() / 200)) << "more than edge points off the modelled noise";
	EXPECT_GT(median(calibration), 0.005) << "the lasers' calibration errors move the points";
}

TEST(CameraErrors, ExposureGainIsStationaryWithTheDocumentedSpreadAndFixedBySeed)
{
	const CameraRealism p;
	std::vector<double> x;
	for (int k = 0; k < 3000; ++k) x.push_back(std::log(exposureGain(p, 5, k)));
	const double stationary = p.exposure_step / std::sqrt(1 - p.exposure_ar * p.exposure_ar);
	EXPECT_NEAR(stats(x).sd, stationary, 0.15 * stationary);
	EXPECT_NEAR(stats(x).mean, 0, 0.02);
	double step = 0;
	for (std::size_t k = 1; k < x.size(); ++k) step += (x[k] - x[k - 1]) * (x[k] - x[k - 1]);
	// Frame to frame the log gain changes by sqrt(2 (1 - a)) of its spread: a slow drift, not flicker.
	EXPECT_NEAR(std::sqrt(step / static_cast<double>(x.size() - 1)), stationary * std::sqrt(2 * (1 - p.exposure_ar)), 0.15 * stationary);
	EXPECT_EQ(exposureGain(p, 5, 17), exposureGain(p, 5, 17));
	EXPECT_NE(exposureGain(p, 5, 17), exposureGain(p, 6, 17));
}

TEST(CameraErrors, BlurGainAndNoiseHaveTheDocumentedSizes)
{
	CameraRealism p;
	// Noise on a flat grey 100 under gain 1.2: mean 120, variance 2^2 + 0.04 * 120.
	cv::Mat flat(200, 200, CV_32F, cv::Scalar(100));
	Rng rng(4);
	applyCameraErrors(flat, p, 1.2, rng);
	cv::Scalar mean, sd;
	cv::meanStdDev(flat, mean, sd);
	EXPECT_NEAR(mean[0], 120, 0.05);
	EXPECT_NEAR(sd[0], std::sqrt(4 + 0.04 * 120), 0.05);
	// Blur alone on a step between columns 49 and 50: column 50 holds 200 times the half of a sampled
	// Gaussian of sigma 0.6 px (7 taps) from its centre on.
	p.read_noise = p.shot_noise_gain = 0;
	cv::Mat step(20, 100, CV_32F, cv::Scalar(0));
	step.colRange(50, 100).setTo(200);
	applyCameraErrors(step, p, 1.0, rng);
	double half = 0;
	for (int x = 0; x <= 3; ++x) half += std::exp(-x * x / (2 * 0.36));
	const double total = 2 * half - 1;
	EXPECT_NEAR(step.at<float>(10, 50), 200 * half / total, 0.01);
	EXPECT_GT(step.at<float>(10, 50), 150);
	EXPECT_LT(step.at<float>(10, 50), 190);
	EXPECT_NEAR(step.at<float>(10, 49), 200 - step.at<float>(10, 50), 0.01);
	// Saturation: a bright level cannot exceed 255 before the noise.
	cv::Mat bright(50, 50, CV_32F, cv::Scalar(250));
	applyCameraErrors(bright, p, 1.2, rng);
	EXPECT_NEAR(bright.at<float>(25, 25), 255, 1e-3);
}
