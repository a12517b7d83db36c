// Two-view geometry against closed forms: model fitting, decomposition, model selection, pose
// recovery for general and planar scenes with and without noise, triangulation accuracy.
#include <gtest/gtest.h>
#include <vlo/vo/triangulation.h>
#include <vlo/vo/two_view.h>

#include <random>

#include "synthetic_scene.h"

using namespace vlo;
using namespace vlo::vo;

namespace
{
struct Pairs
{
	std::vector<Vec2> x1, x2;
	std::vector<Vec3> X;  ///< camera 1
};

/// Points seen by camera 1 at the origin and camera 2 = T21 * camera 1; planar puts them on a plane.
Pairs makePairs(const PinholeCamera& cam, const SE3& T21, bool planar, double noise, int n, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> u(0, 1);
	std::normal_distribution<double> g(0, noise > 0 ? noise : 1);
	Pairs p;
	while (static_cast<int>(p.X.size()) < n)
	{
		const Vec2 px(u(rng) * cam.width, u(rng) * cam.height);
		const double depth = planar ? 0 : 4 + 30 * u(rng);
		Vec3 X = unproject(cam, px);
		if (planar)
		{
			// Plane through (0, 0, 15) tilted 30 degrees about x: n . X = d.
			const Vec3 nrm = Vec3(0, std::sin(0.5), std::cos(0.5)).normalized();
			const double d = nrm.dot(Vec3(0, 0, 15));
			X *= d / nrm.dot(X);
			if (X.z() <= 1) continue;
		}
		else
			X *= depth;
		const Vec3 X2 = T21 * X;
		if (X2.z() <= 0.5) continue;
		Vec2 a = project(cam, X), b = project(cam, X2);
		if (!inImage(cam, b)) continue;
		if (noise > 0) a += Vec2(g(rng), g(rng)), b += Vec2(g(rng), g(rng));
		p.x1.push_back(a);
		p.x2.push_back(b);
		p.X.push_back(X);
	}
	return p;
}

SE3 sampleMotion()
{
	// Forward driving with a turn and some sideways drift: the KITTI case.
	return makeSE3(Eigen::AngleAxisd(0.05, Vec3(0.1, 1, 0.05).normalized()).toRotationMatrix(), Vec3(0.2, -0.05, -1.0));
}

double rotErrDeg(const Mat3& A, const Mat3& B) { return Eigen::AngleAxisd(A.transpose() * B).angle() * 180 / M_PI; }
double dirErrDeg(const Vec3& a, const Vec3& b) { return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / M_PI; }

/// The sampled motion reconstructed from 300 pairs, noise-free (exactly) and with 0.5 px noise (within
/// the bounds), by the model that suits the scene: the fundamental matrix, or for a plane the homography.
void expectSampledMotionRecovered(bool planar, unsigned seed, double noisy_rot_err_deg, double noisy_dir_err_deg)
{
	const auto cam = test::kittiCamera();
	const SE3 T = sampleMotion();
	InitOptions opt;
	for (double noise : {0.0, 0.5})
	{
		const Pairs p = makePairs(cam, T, planar, noise, 300, seed);
		const auto r = reconstructTwoView(cam, p.x1, p.x2, opt);
		ASSERT_TRUE(r.ok) << r.reason;
		EXPECT_EQ(r.model, planar ? 'H' : 'F') << "R_H " << r.rh;
		EXPECT_EQ(r.rh > 0.45, planar) << "R_H " << r.rh;
		EXPECT_LT(rotErrDeg(r.T21.linear(), T.linear()), noise > 0 ? noisy_rot_err_deg : 1e-6);
		EXPECT_LT(dirErrDeg(r.T21.translation(), T.translation()), noise > 0 ? noisy_dir_err_deg : 1e-6);
		EXPECT_GT(r.n_good, 240);
	}
}
}  // namespace

TEST(TwoView, ModelsFitExactCorrespondences)
{
	const auto cam = test::kittiCamera();
	const SE3 T = sampleMotion();
	const Pairs gen = makePairs(cam, T, false, 0, 8, 1);
	const Mat3 F = detail::fundamental8(gen.x1, gen.x2);
	for (std::size_t i = 0; i < gen.x1.size(); ++i)
		EXPECT_NEAR(gen.x2[i].homogeneous().dot(F * gen.x1[i].homogeneous()) / F.norm(), 0, 1e-6);
	const Pairs pl = makePairs(cam, T, true, 0, 8, 2);
	const Mat3 H = detail::homographyDLT(pl.x1, pl.x2);
	for (std::size_t i = 0; i < pl.x1.size(); ++i) EXPECT_LT(((H * pl.x1[i].homogeneous()).hnormalized() - pl.x2[i]).norm(), 1e-6);
}

TEST(TwoView, EssentialDecompositionContainsTruePose)
{
	const auto cam = test::kittiCamera();
	const SE3 T = sampleMotion();
	const Mat3 E = skew(T.translation()) * T.linear();
	const auto ms = detail::decomposeEssential(E);
	ASSERT_EQ(ms.size(), 4u);
	int found = 0;
	for (const auto& m : ms)
		if (rotErrDeg(m.R, T.linear()) < 1e-6 && dirErrDeg(m.t, T.translation()) < 1e-6) ++found;
	EXPECT_EQ(found, 1);
	// The cheirality check puts every point in front only for the true motion.
	const Pairs p = makePairs(cam, T, false, 0, 100, 3);
	const std::vector<char> all(p.x1.size(), 1);
	for (const auto& m : ms)
	{
		const auto c = detail::checkMotion(m, p.x1, p.x2, all, cam.K(), 4.0);
		const bool truth = rotErrDeg(m.R, T.linear()) < 1e-6 && dirErrDeg(m.t, T.translation()) < 1e-6;
		if (truth)
			EXPECT_EQ(c.n_good, 100);
		else
			EXPECT_LT(c.n_good, 50);
	}
}

TEST(TwoView, GeneralSceneSelectsFundamentalAndTruePose) { expectSampledMotionRecovered(false, 4, 0.2, 2.0); }

TEST(TwoView, PlanarSceneSelectsHomographyAndTruePose) { expectSampledMotionRecovered(true, 5, 0.3, 3.0); }

TEST(TwoView, ReportsTooLittleParallax)
{
	const auto cam = test::kittiCamera();
	// 5 cm sideways over points 4-34 m away: well under a degree of parallax.
	const SE3 T = makeSE3(Mat3::Identity(), Vec3(0.05, 0, 0));
	const Pairs p = makePairs(cam, T, false, 0.5, 300, 6);
	const auto r = reconstructTwoView(cam, p.x1, p.x2, InitOptions());
	EXPECT_FALSE(r.ok);
	EXPECT_FALSE(r.reason.empty());
	EXPECT_NE(r.reason.find("parallax"), std::string::npos) << r.reason;
}

TEST(TwoView, ReportsTooFewMatches)
{
	const auto cam = test::kittiCamera();
	const Pairs p = makePairs(cam, sampleMotion(), false, 0, 5, 7);
	const auto r = reconstructTwoView(cam, p.x1, p.x2, InitOptions());
	EXPECT_FALSE(r.ok);
	EXPECT_NE(r.reason.find("too few matches"), std::string::npos) << r.reason;
}

TEST(Triangulation, NoisyPointsWithinTolerance)
{
	const auto cam = test::kittiCamera();
	const SE3 T1 = SE3::Identity();
	const SE3 T2 = makeSE3(Mat3::Identity(), Vec3(-1.0, 0, 0));  // 1 m baseline
	const Pairs p = makePairs(cam, T2, false, 0.5, 200, 8);
	const Mat3 Kinv = cam.K().inverse();
	for (std::size_t i = 0; i < p.X.size(); ++i)
	{
		Vec3 X;
		ASSERT_TRUE(triangulate(T1, T2, Kinv * p.x1[i].homogeneous(), Kinv * p.x2[i].homogeneous(), X));
		// Depth error of stereo: z^2 / (f b) * disparity error (~0.7 px), with a margin of 4 sigma.
		const double z = p.X[i].z(), tol = 4 * z * z / (cam.fx * 1.0) * 0.71 + 1e-3;
		EXPECT_NEAR(X.z(), z, tol) << "point " << i;
		EXPECT_LT((X - p.X[i]).norm(), tol * 1.2);
	}
	Vec3 X;
	EXPECT_TRUE(triangulate(T1, T2, Kinv * p.x1[0].homogeneous(), Kinv * p.x2[0].homogeneous(), X));
}
