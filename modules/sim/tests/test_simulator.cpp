// Whole-simulator checks on short drives: determinism, LiDAR vs exact world geometry from the ground
// truth poses, LiDAR vs the rendered camera depth, and images that feature detectors can use.
// ctest runs each test in its own process; all of them in one process would run out of MRPT's
// texture units (never freed), so use --gtest_filter when running this binary by hand.
#include "sim_test_util.h"

#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/sim/camera_sim.h>
#include <vlo/sim/simulator.h>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

using namespace vlo;
using namespace vlo::sim;

namespace
{
SimConfig config(Scenario sc, const LidarModel& lidar, int frames, uint64_t seed, bool noise = false)
{
	SimConfig c;
	c.scenario = sc, c.lidar = lidar, c.frames = frames, c.seed = seed;
	if (!noise) c.range_noise = c.image_noise = c.dropout = 0;
	return c;
}

cv::Mat asMat(const mrpt::img::CImage& img)
{
	cv::Mat m(static_cast<int>(img.getHeight()), static_cast<int>(img.getWidth()), CV_8UC1);
	for (int r = 0; r < m.rows; ++r) std::memcpy(m.ptr(r), img.ptrLine<uint8_t>(r), m.cols);
	return m;
}

bool sameImage(const mrpt::img::CImage& a, const mrpt::img::CImage& b)
{
	if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) return false;
	for (unsigned r = 0; r < a.getHeight(); ++r)
		if (std::memcmp(a.ptrLine<uint8_t>(r), b.ptrLine<uint8_t>(r), a.getWidth()) != 0) return false;
	return true;
}

bool sameScan(const PointCloud& a, const PointCloud& b)
{
	return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(LidarPoint)) == 0);
}

/// Optional artefact for a human: the image with LiDAR points projected (VLO_SIM_DEBUG_DIR).
void saveOverlay(const Frame& f, const char* name)
{
	const char* dir = std::getenv("VLO_SIM_DEBUG_DIR");
	if (!dir) return;
	cv::Mat gray = asMat(f.image), out;
	cv::cvtColor(gray, out, cv::COLOR_GRAY2BGR);
	const Eigen::Isometry3d CL = f.rig.camera_T_lidar();
	for (const auto& p : f.scan)
	{
		const Eigen::Vector3d c = CL * Eigen::Vector3d(p.x, p.y, p.z);
		if (c.z() < 1) continue;
		const double u = f.rig.camera.fx * c.x() / c.z() + f.rig.camera.cx, v = f.rig.camera.fy * c.y() / c.z() + f.rig.camera.cy;
		const double h = std::clamp(c.z() / 40.0, 0.0, 1.0);
		cv::circle(out, cv::Point(int(std::lround(u)), int(std::lround(v))), 1, cv::Scalar(255 * h, 80, 255 * (1 - h)), -1);
	}
	mrpt::img::CImage(out, mrpt::img::DEEP_COPY).saveToFile(std::string(dir) + "/" + name + ".png");
}
}  // namespace

namespace
{
/// Frame k of a fresh simulator (one simulator at a time: they share MRPT's EGL display).
Frame renderOnce(const SimConfig& cfg, int k, Eigen::Isometry3d* pose = nullptr)
{
	Simulator sim(cfg);
	if (pose) *pose = sim.vehiclePose(k);
	return sim.frame(k);
}
}  // namespace

TEST(Simulator, SameSeedSameBytesOtherSeedOtherWorld)
{
	// Trees: few textures, so three worlds fit in one process (MRPT's texture units are never freed).
	const SimConfig cfg = config(Scenario::Trees, vlp16(), 2, 11, true);
	Eigen::Isometry3d pa, pb;
	const Frame fa = renderOnce(cfg, 1, &pa), fb = renderOnce(cfg, 1, &pb);
	EXPECT_TRUE(sameImage(fa.image, fb.image));
	EXPECT_TRUE(sameScan(fa.scan, fb.scan));
	EXPECT_TRUE(pa.isApprox(pb, 0));
	SimConfig other = cfg;
	other.seed = 12;
	EXPECT_FALSE(sameImage(fa.image, renderOnce(other, 1).image));
}

TEST(Simulator, OnlyOneAtATime)
{
	Simulator a(config(Scenario::Trees, vlp16(), 1, 1));
	EXPECT_THROW(Simulator b(config(Scenario::Trees, vlp16(), 1, 1)), std::logic_error);
}

TEST(Simulator, LidarPointsLieOnTheWorldSeenFromTheGroundTruthPose)
{
	Simulator sim(config(Scenario::Urban, hdl64(), 6, 3));
	const int k = 5;
	const Frame f = sim.frame(k);
	ASSERT_GT(f.scan.size(), 90000u);
	// The world seen from the pose the frame was rendered from: ground truth (relative to frame 0)
	// composed with frame 0's world pose.
	const Eigen::Isometry3d V = sim.vehiclePose(0) * sim.groundTruth()[k].pose;
	EXPECT_TRUE(V.isApprox(sim.vehiclePose(k), 1e-9));
	const Eigen::Isometry3d L = V * f.rig.vehicle_T_lidar;
	std::size_t n = 0, exact = 0, onSurface = 0;
	for (std::size_t i = 0; i < f.scan.size(); i += 37)
	{
		const Eigen::Vector3d p(f.scan[i].x, f.scan[i].y, f.scan[i].z);
		double truth = -1;
		++n;
		if (sim.world().raycast(L.translation(), L.linear() * p.normalized(), 150, truth) && std::abs(truth - p.norm()) < 0.02)
			++exact, ++onSurface;
		else  // within a pixel of an edge: must still be on real geometry
			onSurface += test::nearSurface(sim.world(), L * p, 0.02 + 0.0025 * p.norm());
	}
	EXPECT_GT(n, 2500u);
	EXPECT_GE(exact, 0.98 * n);  // the rest sit at edges, poles, foliage
	EXPECT_GE(onSurface, 0.998 * n);
	saveOverlay(f, "urban_overlay");
}

TEST(Simulator, LidarPointsProjectOntoMatchingCameraDepth)
{
	Simulator sim(config(Scenario::Urban, hdl64(), 1, 4));
	RenderedView depth;
	const Frame f = sim.frame(0, &depth);
	const Eigen::Isometry3d CL = f.rig.camera_T_lidar();
	const PinholeCamera& K = f.rig.camera;
	std::size_t n = 0, agree = 0;
	std::vector<double> rel;
	for (const auto& p : f.scan)
	{
		const Eigen::Vector3d c = CL * Eigen::Vector3d(p.x, p.y, p.z);
		if (c.z() < 2) continue;
		const double u = K.fx * c.x() / c.z() + K.cx, v = K.fy * c.y() / c.z() + K.cy;
		if (u < 0 || v < 0 || u > K.width - 1 || v > K.height - 1) continue;
		const float z = CameraSim::depthAt(depth, u, v);
		++n;
		if (z > 0 && std::abs(z - c.z()) < 0.03 + 0.005 * c.z()) ++agree, rel.push_back((z - c.z()) / c.z());
	}
	EXPECT_GT(n, 15000u);  // the camera sees about a sixth of the sweep
	// Disagreement only at occlusion edges (the sensors are 0.28 m apart) ...
	EXPECT_GE(agree, 0.95 * n) << agree << " of " << n;
	// ... and no bias where they agree (a wrong extrinsic or intrinsic would show here).
	std::nth_element(rel.begin(), rel.begin() + rel.size() / 2, rel.end());
	EXPECT_LT(std::abs(rel[rel.size() / 2]), 2e-4);
}

namespace
{
/// FAST corners (threshold 20) in frame k of a noisy drive.
std::size_t corners(Scenario sc, int frames, int k)
{
	Simulator sim(config(sc, vlp16(), frames, 2, true));
	const Frame f = sim.frame(k);
	std::vector<cv::KeyPoint> kp;
	cv::FAST(asMat(f.image), kp, 20, true);
	saveOverlay(f, ("scenario_" + scenarioName(sc)).c_str());
	return kp.size();
}
}  // namespace

TEST(Simulator, UrbanImagesHaveCorners) { EXPECT_GT(corners(Scenario::Urban, 1, 0), 1500u); }
TEST(Simulator, TreesImagesHaveCorners) { EXPECT_GT(corners(Scenario::Trees, 1, 0), 1500u); }
TEST(Simulator, CorridorImagesHaveCornersBetweenTheWalls) { EXPECT_GT(corners(Scenario::Corridor, 40, 20), 1500u); }

TEST(Simulator, KittiTrajectoryIsFollowed)
{
	// The first poses of KITTI sequence 00 (the shared archive holds all of them).
	const char* lines[] = {
		"1.000000e+00 9.043680e-12 2.326809e-11 5.551115e-17 9.043683e-12 1.000000e+00 2.392370e-10 3.330669e-16 2.326810e-11 2.392370e-10 9.999999e-01 -4.440892e-16",
		"9.999978e-01 5.272628e-04 -2.066935e-03 -4.690294e-02 -5.296506e-04 9.999992e-01 -1.154865e-03 -2.839928e-02 2.066324e-03 1.155958e-03 9.999971e-01 8.586941e-01",
		"9.999910e-01 1.048972e-03 -4.131348e-03 -9.374345e-02 -1.058514e-03 9.999968e-01 -2.308104e-03 -5.676064e-02 4.128913e-03 2.312456e-03 9.999887e-01 1.716275e+00"};
	const std::string path = testing::TempDir() + "vlo_sim_kitti_poses.txt";
	{
		std::ofstream out(path);
		for (const char* l : lines) out << l << "\n";
	}
	SimConfig cfg = config(Scenario::Urban, vlp16(), 3, 1);
	cfg.kitti_poses = path;
	Simulator sim(cfg);
	// Camera 0 moves 1.716 m forward by frame 2: so does the vehicle (no rotation to speak of).
	const Trajectory gt = sim.groundTruth();
	ASSERT_EQ(gt.size(), 3u);
	EXPECT_NEAR(gt[2].pose.translation().x(), 1.716, 0.01);
	EXPECT_NEAR(gt[2].t, 0.2, 1e-12);
	const Frame f = sim.frame(2);
	EXPECT_GT(f.scan.size(), 10000u);
	cfg.frames = 4;
	EXPECT_THROW(Simulator{cfg}, InputError);  // only 3 poses
}
