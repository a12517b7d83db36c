// Epipolar culling (eqs. 2-4) on hand-built cases.
#include <gtest/gtest.h>
#include <vlo/scale/epipolar.h>

#include <cmath>

#include "pinhole.h"

using namespace vlo::scale;
using namespace vlo::scale::test;

namespace
{
/// The camera moves sideways along its x axis: X_cur = X_prev - (b, 0, 0), epipolar lines are the rows.
Eigen::Isometry3d sideways(double b)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation() = Eigen::Vector3d(-b, 0, 0);
	return T;
}
}  // namespace

TEST(Epipolar, SidewaysMotionGivesHorizontalLines)
{
	const Eigen::Matrix3d F = fundamentalMatrix(kittiK(), sideways(0.5));
	const Eigen::Vector3d l = epipolarLine(F, {400.f, 200.f});
	EXPECT_NEAR(l.x() / l.norm(), 0, 1e-12);  // A = 0: the line is y = 200
	EXPECT_NEAR(normalError(l, {350.f, 200.f}), 0.0, 1e-9);
	EXPECT_NEAR(normalError(l, {350.f, 201.f}), 1.0, 1e-9);
	EXPECT_NEAR(normalError(l, {123.f, 199.6f}), 0.4, 1e-4);
	EXPECT_NEAR(absCosToLine(l, {5.f, 0.f}), 1.0, 1e-12);  // gradient along the line
	EXPECT_NEAR(absCosToLine(l, {0.f, -5.f}), 0.0, 1e-12);  // across it
	EXPECT_NEAR(absCosToLine(l, {1.f, 1.f}), std::sqrt(0.5), 1e-7);
	EXPECT_EQ(absCosToLine(l, {0.f, 0.f}), 0.0);  // flat patch
}

TEST(Epipolar, CullMatchKeepsOnTheLineAndDropsOnePixelOffOrPerpendicularGradient)
{
	const Eigen::Matrix3d F = fundamentalMatrix(kittiK(), sideways(0.5));
	const ScaleOptions opt;  // 0.5 px and |cos| 0.5, the paper's values
	const cv::Point2f prev(400, 200), along(8, 0), across(0, 8);

	auto on = cullMatch(F, prev, {370, 200}, along, opt);
	EXPECT_EQ(on.rejected_by, Stage::None);
	EXPECT_NEAR(on.normal_error, 0, 1e-9);
	EXPECT_NEAR(on.abs_cos, 1, 1e-12);

	EXPECT_EQ(cullMatch(F, prev, {370, 201}, along, opt).rejected_by, Stage::Epipolar);  // 1 px off
	EXPECT_EQ(cullMatch(F, prev, {370, 199}, along, opt).rejected_by, Stage::Epipolar);
	EXPECT_EQ(cullMatch(F, prev, {370, 200.4f}, along, opt).rejected_by, Stage::None);  // 0.4 px: kept
	EXPECT_EQ(cullMatch(F, prev, {370, 200}, across, opt).rejected_by, Stage::Gradient);  // perpendicular
	// |cos| = cos 45 deg = 0.71 is kept, cos 60 deg = 0.5 is not (strictly greater).
	EXPECT_EQ(cullMatch(F, prev, {370, 200}, {1, 1}, opt).rejected_by, Stage::None);
	EXPECT_EQ(cullMatch(F, prev, {370, 200}, {0.5f, std::sqrt(3.f) / 2}, opt).rejected_by, Stage::Gradient);

	// Ablation switches.
	ScaleOptions off = opt;
	off.cull_epipolar = false;
	EXPECT_EQ(cullMatch(F, prev, {370, 210}, along, off).rejected_by, Stage::None);
	off.cull_gradient = false;
	EXPECT_EQ(cullMatch(F, prev, {370, 210}, across, off).rejected_by, Stage::None);
}

TEST(Epipolar, GeneralMotionTrueMatchesLieOnTheLineWhateverTheTranslationScale)
{
	const Eigen::Matrix3d K = kittiK();
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.rotate(Eigen::AngleAxisd(0.03, Eigen::Vector3d(0.2, 1, 0.1).normalized()));
	T.translation() = Eigen::Vector3d(0.1, -0.05, -1.2);
	for (double k : {0.01, 1.0, 30.0})
	{
		Eigen::Isometry3d Tk = T;
		Tk.translation() *= k;
		const Eigen::Matrix3d F = fundamentalMatrix(K, Tk);
		for (const Eigen::Vector3d& X : {Eigen::Vector3d(3, 1, 12), Eigen::Vector3d(-8, -2, 25), Eigen::Vector3d(0.5, 1.5, 6)})
		{
			const cv::Point2f a = project(K, X), b = project(K, T * X);
			EXPECT_LT(normalError(epipolarLine(F, a), b), 1e-3) << "k " << k;
		}
	}
	// A match moved 1 px across the epipolar line has a normal error of 1 px.
	const Eigen::Matrix3d F = fundamentalMatrix(K, T);
	const Eigen::Vector3d X(3, 1, 12);
	const cv::Point2f a = project(K, X), b = project(K, T * X);
	const Eigen::Vector3d l = epipolarLine(F, a);
	const cv::Point2f n(static_cast<float>(l.x() / std::hypot(l.x(), l.y())), static_cast<float>(l.y() / std::hypot(l.x(), l.y())));
	EXPECT_NEAR(normalError(l, b + n), 1.0, 1e-3);
	EXPECT_NEAR(absCosToLine(l, n), 0.0, 1e-6);  // the line's normal is perpendicular to it
}

TEST(Epipolar, NoTranslationNoLine)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.rotate(Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY()));
	const Eigen::Matrix3d F = fundamentalMatrix(kittiK(), T);
	EXPECT_TRUE(F.isZero());
	EXPECT_TRUE(std::isinf(normalError(epipolarLine(F, {100.f, 100.f}), {90.f, 100.f})));
	EXPECT_EQ(cullMatch(F, {100, 100}, {90, 100}, {1, 0}, ScaleOptions{}).rejected_by, Stage::Epipolar);
}
