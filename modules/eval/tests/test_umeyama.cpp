#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/eval/umeyama.h>

#include <random>

using namespace vlo;
using namespace vlo::eval;

namespace
{
std::vector<Eigen::Vector3d> randomPoints(std::size_t n, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> u(-10, 10);
	std::vector<Eigen::Vector3d> p(n);
	for (auto& x : p) x = Eigen::Vector3d(u(rng), u(rng), u(rng));
	return p;
}

Sim3 knownTransform(double s)
{
	Sim3 T;
	T.s = s;
	T.R = Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -1, 0.5).normalized()).toRotationMatrix();
	T.t = Eigen::Vector3d(4, -2, 7);
	return T;
}

std::vector<Eigen::Vector3d> transformAll(const Sim3& T, const std::vector<Eigen::Vector3d>& p)
{
	std::vector<Eigen::Vector3d> q;
	for (const auto& x : p) q.push_back(T * x);
	return q;
}
}  // namespace

TEST(Umeyama, RecoversRigidTransformExactly)
{
	const auto src = randomPoints(50, 1);
	const Sim3 T = knownTransform(1.0);
	const Sim3 E = umeyama(src, transformAll(T, src), false);
	EXPECT_DOUBLE_EQ(E.s, 1.0);
	EXPECT_TRUE(E.R.isApprox(T.R, 1e-12));
	EXPECT_TRUE(E.t.isApprox(T.t, 1e-12));
}

TEST(Umeyama, RecoversSimilarityExactly)
{
	const auto src = randomPoints(50, 2);
	const Sim3 T = knownTransform(2.7);
	const Sim3 E = umeyama(src, transformAll(T, src), true);
	EXPECT_NEAR(E.s, 2.7, 1e-12);
	EXPECT_TRUE(E.R.isApprox(T.R, 1e-12));
	EXPECT_TRUE(E.t.isApprox(T.t, 1e-11));
	// Without scale, the rotation is still right (the scale only stretches about the centroid).
	EXPECT_TRUE(umeyama(src, transformAll(T, src), false).R.isApprox(T.R, 1e-12));
}

TEST(Umeyama, NoisyPointsGiveApproximateTransform)
{
	const auto src = randomPoints(2000, 3);
	const Sim3 T = knownTransform(0.4);
	auto dst = transformAll(T, src);
	std::mt19937 rng(4);
	std::normal_distribution<double> noise(0, 0.01);
	for (auto& x : dst) x += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
	const Sim3 E = umeyama(src, dst, true);
	// 1 cm noise on ~6 m spread points, 2000 of them: errors of order 1e-4.
	EXPECT_NEAR(E.s, 0.4, 1e-3);
	EXPECT_LT(Eigen::AngleAxisd(E.R.transpose() * T.R).angle(), 1e-3);
	EXPECT_LT((E.t - T.t).norm(), 1e-2);
}

TEST(Umeyama, NeverReturnsAReflection)
{
	// A mirrored planar set: the best orthogonal fit would be a reflection; Umeyama's sign fix keeps a rotation.
	std::vector<Eigen::Vector3d> src{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {3, 1, 0}}, dst;
	for (const auto& p : src) dst.push_back(Eigen::Vector3d(p.x(), -p.y(), 0));
	const Sim3 E = umeyama(src, dst, false);
	EXPECT_NEAR(E.R.determinant(), 1.0, 1e-12);
}

TEST(Umeyama, CollinearPointsGetTheSmallestRotation)
{
	std::vector<Eigen::Vector3d> line;
	for (int i = 0; i < 20; ++i) line.push_back(Eigen::Vector3d(0.9 * i, 0, 0));
	// Identical straight trajectories: identity, not some roll about the line.
	const Sim3 I = umeyama(line, line, true);
	EXPECT_TRUE(I.R.isApprox(Eigen::Matrix3d::Identity(), 1e-12));
	EXPECT_NEAR(I.s, 1.0, 1e-12);
	EXPECT_LT(I.t.norm(), 1e-12);
	// A yaw of 0.5 rad applied to the line is recovered as exactly that yaw.
	Sim3 T;
	T.R = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	T.t = Eigen::Vector3d(1, 2, 3);
	const Sim3 E = umeyama(line, transformAll(T, line), false);
	EXPECT_TRUE(E.R.isApprox(T.R, 1e-12));
	EXPECT_TRUE(E.t.isApprox(T.t, 1e-12));
}

TEST(Umeyama, ScaleOfMotionlessSourceIsAnInputError)
{
	const std::vector<Eigen::Vector3d> src(5, Eigen::Vector3d(1, 1, 1)), dst = randomPoints(5, 5);
	EXPECT_THROW(umeyama(src, dst, true), InputError);
	EXPECT_NO_THROW(umeyama(src, dst, false));
	EXPECT_THROW(umeyama(src, {}, false), std::invalid_argument);
}
