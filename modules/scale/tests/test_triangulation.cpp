// Midpoint triangulation: exact depth on noise-free correspondences, v proportional to the VO scale.
#include <gtest/gtest.h>
#include <vlo/scale/triangulation.h>

#include <random>

#include "pinhole.h"

using namespace vlo::scale;
using namespace vlo::scale::test;

TEST(Triangulation, ExactDepthOnNoiseFreeCorrespondences)
{
	const Eigen::Matrix3d K = kittiK(), Kinv = K.inverse();
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> u(-1, 1);
	double worst = 0;
	for (int i = 0; i < 500; ++i)
	{
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();  // a forward-driving camera, turning a little
		T.rotate(Eigen::AngleAxisd(0.05 * u(rng), Eigen::Vector3d(0.1 * u(rng), 1, 0.1 * u(rng)).normalized()));
		T.translation() = Eigen::Vector3d(0.2 * u(rng), 0.05 * u(rng), -1.0 + 0.2 * u(rng));
		const double z = 5 + 25 * (u(rng) + 1);
		const Eigen::Vector3d X(z * 0.5 * u(rng), z * 0.15 * u(rng), z);
		const cv::Point2f a = project(K, X), b = project(K, T * X);
		const Triangulated t = triangulateMidpoint(Kinv, T, a, b, 0.1);
		if (t.status != TriangulationStatus::Ok) continue;  // near the epipole: too little parallax
		worst = std::max(worst, std::abs(t.depth / X.z() - 1));
		// The VO's scale error k scales the visual depth by k: s = d / v = 1 / k.
		Eigen::Isometry3d Tk = T;
		Tk.translation() *= 0.7;
		EXPECT_NEAR(triangulateMidpoint(Kinv, Tk, a, b, 0.1).depth / t.depth, 0.7, 1e-9);
	}
	// Float pixels (1e-4 px) are the only error source.
	EXPECT_LT(worst, 2e-4);
}

TEST(Triangulation, DepthIsAlongTheOpticalAxisOfThePreviousCamera)
{
	const Eigen::Matrix3d K = kittiK();
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation() = Eigen::Vector3d(-1.0, 0, 0);  // sideways: the best parallax
	const Eigen::Vector3d X(4, -1, 10);
	const Triangulated t = triangulateMidpoint(K.inverse(), T, project(K, X), project(K, T * X), 0.5);
	ASSERT_EQ(t.status, TriangulationStatus::Ok);
	EXPECT_NEAR(t.depth, 10.0, 1e-3);  // z, not the range 10.8
	EXPECT_NEAR((t.X - X).norm(), 0, 1e-3);
	EXPECT_NEAR(t.parallax_deg, std::acos(X.normalized().dot((X - Eigen::Vector3d(1, 0, 0)).normalized())) * 180 / M_PI, 1e-3);
}

TEST(Triangulation, RejectsTooLittleParallaxAndPointsBehind)
{
	const Eigen::Matrix3d K = kittiK(), Kinv = K.inverse();
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation() = Eigen::Vector3d(-0.1, 0, 0);
	const Eigen::Vector3d far(0, 0, 100);  // 10 cm baseline at 100 m: 0.057 deg
	EXPECT_EQ(triangulateMidpoint(Kinv, T, project(K, far), project(K, T * far), 0.5).status,
		TriangulationStatus::LowParallax);
	EXPECT_EQ(triangulateMidpoint(Kinv, T, project(K, far), project(K, T * far), 0.01).status, TriangulationStatus::Ok);
	// Rays that diverge (the match moved the wrong way) meet behind the cameras.
	const cv::Point2f a = project(K, {0, 0, 10});
	EXPECT_EQ(triangulateMidpoint(Kinv, T, a, a + cv::Point2f(10, 0), 0.1).status, TriangulationStatus::Behind);
	// No translation: nothing to triangulate.
	EXPECT_EQ(triangulateMidpoint(Kinv, Eigen::Isometry3d::Identity(), a, a + cv::Point2f(-5, 0), 0.0).status,
		TriangulationStatus::LowParallax);
}
