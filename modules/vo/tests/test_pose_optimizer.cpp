// Pose-only optimisation: a known pose from its points' keypoints, with noise and outliers.
#include <gtest/gtest.h>
#include <vlo/vo/map_point.h>
#include <vlo/vo/optimizer.h>

#include <opencv2/core.hpp>

#include <memory>

#include "synthetic_scene.h"

using namespace vlo;
using namespace vlo::vo;

namespace
{
struct Scene
{
	std::vector<std::unique_ptr<MapPoint>> points;
	std::vector<char> injected;  ///< per keypoint: an outlier put there
	TrackedFrame frame;
};

/// n points 5-40 m in front of the camera at Tcw, seen with 0.5 px noise (per level) at keypoints
/// of random pyramid levels; every fifth keypoint moved 20-60 px instead.
Scene makeScene(const SE3& Tcw, const PinholeCamera& cam, const ScalePyramid& pyr, int n)
{
	cv::RNG rng(3);
	Scene s;
	auto feat = std::make_shared<Features>();
	for (int i = 0; i < n; ++i)
	{
		const Vec2 px(rng.uniform(20.0, cam.width - 20.0), rng.uniform(20.0, cam.height - 20.0));
		const Vec3 Xc = rng.uniform(5.0, 40.0) * unproject(cam, px);
		s.points.push_back(std::make_unique<MapPoint>(i, Tcw.inverse() * Xc, nullptr));
		const int level = rng.uniform(0, pyr.levels);
		Vec2 seen = px + 0.5 * pyr.scale[static_cast<std::size_t>(level)] * Vec2(rng.gaussian(1), rng.gaussian(1));
		const bool outlier = i % 5 == 0;
		if (outlier) seen += rng.uniform(20.0, 60.0) * Vec2(std::cos(i), std::sin(i));
		s.injected.push_back(outlier);
		cv::KeyPoint k(cv::Point2f(float(seen.x()), float(seen.y())), 31.f, 0.f, 0.f, level);
		feat->keys.push_back(k);
	}
	s.frame = TrackedFrame(0, 0.0, feat);
	for (int i = 0; i < n; ++i) s.frame.points[static_cast<std::size_t>(i)] = s.points[static_cast<std::size_t>(i)].get();
	return s;
}
}  // namespace

TEST(PoseOptimizer, RecoversThePoseAndMarksTheOutliers)
{
	const auto cam = test::kittiCamera();
	const ScalePyramid pyr(8, 1.2);
	SE3 truth = SE3::Identity();
	truth.linear() = Eigen::AngleAxisd(0.1, Vec3(0.2, 1, 0.1).normalized()).toRotationMatrix();
	truth.translation() = Vec3(0.4, -0.1, 1.2);
	Scene s = makeScene(truth, cam, pyr, 300);
	// Start 3 degrees and 0.5 m off, as a poor motion model would.
	s.frame.Tcw = truth;
	s.frame.Tcw.linear() = Eigen::AngleAxisd(0.05, Vec3(1, 0, 0)).toRotationMatrix() * truth.linear();
	s.frame.Tcw.translation() += Vec3(0.3, 0.2, -0.35);
	const int inliers = optimizePose(s.frame, cam, pyr, 4, 10, 5.991);

	const SE3 d = truth.inverse() * s.frame.Tcw;
	EXPECT_LT(d.translation().norm(), 0.02);
	EXPECT_LT(Eigen::AngleAxisd(d.linear()).angle() * 180 / M_PI, 0.05);
	int caught = 0, wrongly = 0;
	for (std::size_t i = 0; i < s.injected.size(); ++i)
	{
		if (s.injected[i]) caught += s.frame.outlier[i];
		else wrongly += s.frame.outlier[i];
	}
	EXPECT_EQ(60, caught);
	EXPECT_LE(wrongly, 6);  // chi2 at 95 %: about 5 % of the 240 good ones would be 12
	EXPECT_EQ(300 - caught - wrongly, inliers);
	// Rotation stays a rotation.
	EXPECT_NEAR(1.0, s.frame.Tcw.linear().determinant(), 1e-12);
	EXPECT_LT((s.frame.Tcw.linear().transpose() * s.frame.Tcw.linear() - Mat3::Identity()).norm(), 1e-12);
}

// A point behind the camera (a bad match) neither stops the solve nor counts as an inlier.
TEST(PoseOptimizer, PointBehindTheCameraIsAnOutlier)
{
	const auto cam = test::kittiCamera();
	const ScalePyramid pyr(8, 1.2);
	Scene s = makeScene(SE3::Identity(), cam, pyr, 50);
	s.points[1]->pos = Vec3(0.5, 0.2, -8.0);
	const int inliers = optimizePose(s.frame, cam, pyr, 4, 10, 5.991);
	EXPECT_EQ(1, s.frame.outlier[1]);
	EXPECT_GE(inliers, 35);
	EXPECT_LT(s.frame.Tcw.translation().norm(), 0.05);
}
