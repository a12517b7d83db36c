// LoopClosure end to end on synthetic drives: a drifting circuit is closed, and a corridor (two walls
// and a floor), a street of identical facades and a drive without revisits close nothing.
#include <gtest/gtest.h>
#include <vlo/loop/loop_closure.h>

#include "drive.h"

#include <cstdio>

using namespace vlo;
using namespace vlo::loop;
using namespace vlo::loop::test;

namespace
{
constexpr double kDeg = M_PI / 180;

/// A 40 x 40 m square with corners rounded at 5 m, counter-clockwise from (5, 0): 151.4 m a lap.
constexpr double kSide = 30, kRadius = 5, kLap = 4 * kSide + 2 * M_PI * kRadius;
Eigen::Isometry3d squareAt(double s)
{
	s = std::fmod(s, kLap);
	const double piece = kSide + M_PI / 2 * kRadius;
	const int side = static_cast<int>(s / piece);
	const double d = s - side * piece, heading = side * M_PI / 2;
	const Eigen::Vector2d dir(std::cos(heading), std::sin(heading)), left(-dir.y(), dir.x());
	const Eigen::Vector2d starts[4] = {{5, 0}, {40, 5}, {35, 40}, {0, 35}};
	if (d <= kSide)
	{
		const Eigen::Vector2d p = starts[side] + d * dir;
		return pose2d(p.x(), p.y(), heading);
	}
	const double phi = (d - kSide) / kRadius;
	const Eigen::Vector2d centre = starts[side] + kSide * dir + kRadius * left;
	const Eigen::Vector2d p = centre + Eigen::Rotation2Dd(phi) * (-kRadius * left);
	return pose2d(p.x(), p.y(), heading + phi);
}

/// Frame pairs a place apart by whole laps: (i, j) with j the frame one lap after i.
std::vector<std::pair<std::size_t, std::size_t>> lapPairs(const Trajectory& truth, std::size_t frames_per_lap_approx)
{
	std::vector<std::pair<std::size_t, std::size_t>> pairs;
	for (std::size_t j = frames_per_lap_approx; j < truth.size(); ++j)
	{
		std::size_t best = 0;
		double best_d = 1e9;
		for (std::size_t i = 0; i + 50 < j; ++i)
		{
			const double d = (truth[i].pose.translation() - truth[j].pose.translation()).norm();
			if (d < best_d) best_d = d, best = i;
		}
		pairs.emplace_back(best, j);
	}
	return pairs;
}

void print(const DriveResult& r)
{
	for (const auto& l : r.loops)
		std::printf("loop %lld -> %lld: descriptor %.3f yaw %.1f inliers %.2f rms %.3f constraint %.3f drift %.2f path %.0f %s\n",
			l.frame, l.candidate_frame, l.descriptor_distance, l.yaw_deg, l.inlier_fraction, l.rms, l.constraint, l.drift,
			l.path_between, l.accepted ? "accepted" : l.reason.c_str());
}

/// A random city around the square's road, none of it on the road.
World squareCity()
{
	return randomCity(3, -60, 100, -60, 100, 120, [](const Eigen::Vector2d& lo, const Eigen::Vector2d& size) {
		const Eigen::Vector2d hi = lo + size;
		const bool touches_outer = hi.x() > -7 && lo.x() < 47 && hi.y() > -7 && lo.y() < 47;
		const bool inside_inner = lo.x() > 7 && hi.x() < 33 && lo.y() > 7 && hi.y() < 33;
		return touches_outer && !inside_inner;
	});
}

/// The revisit error of the odometry and of the loop-closed trajectory over the lap's pairs.
std::pair<double, double> revisitErrors(const DriveResult& r)
{
	const auto pairs = lapPairs(r.truth, static_cast<std::size_t>(kLap));
	const double before = revisitError(r.truth, r.odometry, pairs), after = revisitError(r.truth, r.corrected, pairs);
	std::printf("keyframes %zu, loops %zu accepted of %zu, revisit error %.3f m -> %.3f m\n", r.keyframes, r.accepted(),
		r.loops.size(), before, after);
	return {before, after};
}
}  // namespace

TEST(LoopClosure, ClosesADriftingSquareCircuit)
{
	const World world = squareCity();
	const Trajectory truth = samplePath(squareAt, 1.25 * kLap);
	// 1 deg of yaw per 40 m side and 1 % of scale: the odometry ends metres off after a lap.
	const DriveResult r = drive(world, truth, 1.01, 1.0 * kDeg / 40);
	print(r);
	const auto [before, after] = revisitErrors(r);
	EXPECT_GT(before, 1.0);
	EXPECT_GE(r.accepted(), 5u);
	EXPECT_LT(after, 0.1);
	ASSERT_EQ(r.corrected.size(), truth.size());
	// Before the first loop nothing was known: the start is the odometry's own start.
	EXPECT_LT((r.corrected.front().pose.translation() - r.odometry.front().pose.translation()).norm(), 1e-9);
}

namespace
{
/// What a registration of the frame against the world's surfaces would give at the true place: the
/// point-to-plane J^T J of the surfaces' points within 80 m ([translation; rotation] of the vehicle
/// in the world, rows n^T [I, -[q - t]x]), scaled by registrationInformation at the scans' 1 cm,
/// as the information of the odometry's motion from the frame before.
FrameInformation registrationOf(const World& world, const Trajectory& truth)
{
	return [&world, &truth](std::size_t i, const Trajectory& odometry) -> std::optional<Matrix6d> {
		std::mt19937 rng(static_cast<unsigned>(i));
		std::uniform_real_distribution<double> u(0, 1);
		const Eigen::Vector3d t = truth[i].pose.translation();
		Matrix6d JtJ = Matrix6d::Zero();
		std::size_t pairs = 0;
		for (const auto& surface : world)
		{
			const Eigen::Vector3d n = surface.a.cross(surface.b).normalized();
			const auto count = static_cast<int>(surface.a.cross(surface.b).norm() * surface.density / 16);
			for (int k = 0; k < count; ++k)
			{
				const Eigen::Vector3d q = surface.o + u(rng) * surface.a + u(rng) * surface.b;
				if ((q - t).head<2>().norm() > 80) continue;
				Eigen::Matrix<double, 6, 1> j;
				j << n, (q - t).cross(n);
				JtJ += j * j.transpose();
				++pairs;
			}
		}
		return relativeInformation(registrationInformation(JtJ, pairs, 0.01), odometry[i - 1].pose);
	};
}
}  // namespace

TEST(LoopClosure, ClosesTheSquareCircuitWithTheRegistrationsInformation)
{
	// As above, the odometry edges weighed by each frame's registration instead of the per-metre model.
	const World world = squareCity();
	const Trajectory truth = samplePath(squareAt, 1.25 * kLap);
	// Without the floor ([loop] odometry_floor_*) the odometry, drifting 5 sigma a frame, holds against
	// the loops: 1.011 m (doc/LOOP.md).
	const DriveResult r = drive(world, truth, 1.01, 1.0 * kDeg / 40, {}, 11, 0, registrationOf(world, truth));
	const auto [before, after] = revisitErrors(r);
	EXPECT_GT(before, 1.0);
	EXPECT_GE(r.accepted(), 5u);
	EXPECT_LT(after, 0.1);
}

namespace
{
World corridor()
{
	World world;
	addRectangle(world, {-300, 4, 0}, {600, 0, 0}, {0, 0, 5}, 3);
	addRectangle(world, {-300, -4, 0}, {600, 0, 0}, {0, 0, 5}, 3);
	addGround(world, -300, 300, -4, 4, 3);
	return world;
}

/// Out along +x at y = -1.5, a U-turn about (60, 0), back along -x at y = 1.5.
Trajectory outAndBack()
{
	const double out = 60, turn = M_PI * 1.5;
	const auto at = [&](double s) {
		if (s < out) return pose2d(s, -1.5, 0);
		if (s < out + turn)
		{
			const double phi = (s - out) / 1.5;
			return pose2d(out + 1.5 * std::sin(phi), -1.5 * std::cos(phi), phi);
		}
		return pose2d(out - (s - out - turn), 1.5, M_PI);
	};
	return samplePath(at, 2 * out + turn);
}
}  // namespace

TEST(LoopClosure, RejectsACorridorAsDegenerate)
{
	// 5 % of scale: the odometry is 3 m off along the corridor when it comes back.
	const DriveResult r = drive(corridor(), outAndBack(), 1.05, 0);
	print(r);
	EXPECT_EQ(r.accepted(), 0u);
	EXPECT_GE(r.rejectedFor("degenerate"), 1u);
}

TEST(LoopClosure, FindsTheSameWhateverTheTiming)
{
	// The loop thread keeping up (a pause after each frame) or far behind: the same candidates, figures
	// and poses, to the bit.
	const DriveResult fast = drive(corridor(), outAndBack(), 1.05, 0), slow = drive(corridor(), outAndBack(), 1.05, 0, {}, 11, 5);
	ASSERT_EQ(fast.loops.size(), slow.loops.size());
	ASSERT_GE(fast.loops.size(), 5u);
	for (std::size_t i = 0; i < fast.loops.size(); ++i)
	{
		EXPECT_EQ(fast.loops[i].candidate_frame, slow.loops[i].candidate_frame);
		EXPECT_EQ(fast.loops[i].inlier_fraction, slow.loops[i].inlier_fraction);
		EXPECT_EQ(fast.loops[i].constraint, slow.loops[i].constraint);
		EXPECT_TRUE(fast.loops[i].candidate_T_current.isApprox(slow.loops[i].candidate_T_current, 0.0));
	}
	ASSERT_EQ(fast.corrected.size(), slow.corrected.size());
	for (std::size_t i = 0; i < fast.corrected.size(); ++i)
		EXPECT_TRUE(fast.corrected[i].pose.isApprox(slow.corrected[i].pose, 0.0));
}

TEST(LoopClosure, RejectsAStreetOfIdenticalFacades)
{
	const World world = facadeStreet(-96, 250, 12);
	const DriveResult r = drive(world, samplePath([](double s) { return pose2d(s, 0, 0); }, 150), 1.0, 0);
	print(r);
	EXPECT_EQ(r.accepted(), 0u);
	EXPECT_GE(r.rejectedFor("drift"), 1u);
}

TEST(LoopClosure, AcceptsNothingOnAStraightDrive)
{
	const World world = randomCity(4, -50, 300, -60, 60, 150, [](const Eigen::Vector2d& lo, const Eigen::Vector2d& size) {
		return lo.y() < 7 && lo.y() + size.y() > -7;
	});
	const DriveResult r = drive(world, samplePath([](double s) { return pose2d(s, 0, 0); }, 250), 1.01, 0.5 * kDeg / 40);
	print(r);
	EXPECT_EQ(r.accepted(), 0u);
	EXPECT_GT(r.keyframes, 100u);
	// Without a loop the corrected trajectory is the odometry.
	ASSERT_EQ(r.corrected.size(), r.odometry.size());
	for (std::size_t i = 0; i < r.odometry.size(); ++i)
		EXPECT_TRUE(r.corrected[i].pose.isApprox(r.odometry[i].pose, 1e-12));
}
