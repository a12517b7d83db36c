// The revisit error on drives whose revisits and errors are known in closed form.
#include <gtest/gtest.h>
#include <vlo/core/se3.h>
#include <vlo/core/units.h>
#include <vlo/eval/evaluate.h>
#include <vlo/eval/kitti_metric.h>
#include <vlo/eval/report.h>
#include <vlo/eval/revisit.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "eval_test_utils.h"

using namespace vlo;
using namespace vlo::eval;
using namespace vlo::test;

namespace
{
constexpr double kSide = 100;  // m: a 400 m lap
constexpr std::size_t kLap = 400;  // poses per lap, 1 m apart
const Eigen::Vector3d kStart(-50, -50, 0);  // the grid's cells on both sides of zero

/// A square circuit driven counter-clockwise from kStart, one pose per metre, 0.1 s apart: pose k is k m
/// along the path; on a corner it already faces the next side.
Trajectory squareCircuit(std::size_t n)
{
	const Eigen::Vector3d dirs[4] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
	Trajectory tr(n);
	for (std::size_t k = 0; k < n; ++k)
	{
		const std::size_t side = (k / std::size_t(kSide)) % 4;
		Eigen::Vector3d p = kStart;
		for (std::size_t s = 0; s < side; ++s) p += kSide * dirs[s];
		p += double(k % std::size_t(kSide)) * dirs[side];
		tr[k].t = 0.1 * k;
		tr[k].pose = makePose(Rz(M_PI / 2 * side), p);
	}
	return tr;
}

/// Poses from `from` on moved by D (on the left): the estimate of a drive that jumped once, e.g. the
/// drift an odometry gathered in a lap.
Trajectory movedFrom(Trajectory tr, std::size_t from, const Eigen::Isometry3d& D)
{
	for (std::size_t k = from; k < tr.size(); ++k) tr[k].pose = D * tr[k].pose;
	return tr;
}

/// Out 100 m east along y = 0, a U-turn of radius 1 m (two poses on it), back west along y = 2.
/// Pose k <= 100 is at x = k; return pose 103 + m at x = 100 - m.
Trajectory outAndBack()
{
	Trajectory tr;
	const auto add = [&](double x, double y, double yaw) {
		tr.push_back({0.1 * tr.size(), makePose(Rz(yaw), Eigen::Vector3d(x, y, 0))});
	};
	for (int k = 0; k <= 100; ++k) add(k, 0, 0);
	for (int m = 1; m <= 2; ++m)
	{
		const double a = -M_PI / 2 + M_PI * m / 3;
		add(100 + std::cos(a), 1 + std::sin(a), a + M_PI / 2);
	}
	for (int m = 0; m <= 100; ++m) add(100 - m, 2, M_PI);
	return tr;
}

/// The number after a top-level key of vlo-eval's JSON.
double jsonNumber(const std::string& json, const std::string& key)
{
	const auto p = json.find("\"" + key + "\": ");
	return p == std::string::npos ? NAN : std::strtod(json.c_str() + p + key.size() + 4, nullptr);
}

constexpr std::size_t kOneAndAHalfLaps = kLap + kLap / 2 + 1;  // poses 0..600
/// Pairs of the 1.5-lap circuit at a 2.5 m radius: poses 398 and 399 (2 and 1 m before the start, 398 and
/// 399 m after it) with pose 0, and each pose j of the second lap (400..600) with j - 400 (the same place).
constexpr std::size_t kCircuitPairs = 2 + (kOneAndAHalfLaps - kLap);
const RevisitOptions kCircuit{2.5, 50};
}  // namespace

TEST(Revisit, SquareCircuitPairsEachSecondLapPoseWithTheFirstLaps)
{
	const Trajectory gt = squareCircuit(kOneAndAHalfLaps);
	const auto pairs = findRevisits(gt, kCircuit);
	ASSERT_EQ(pairs.size(), kCircuitPairs);
	EXPECT_EQ(pairs[0].first, 0u);
	EXPECT_EQ(pairs[0].second, 398u);
	EXPECT_DOUBLE_EQ(pairs[0].distance_m, 2);
	EXPECT_EQ(pairs[1].second, 399u);
	for (std::size_t n = 2; n < pairs.size(); ++n)
	{
		EXPECT_EQ(pairs[n].second, kLap + n - 2);
		EXPECT_EQ(pairs[n].first, n - 2) << "the nearest earlier pose is the same place, not a neighbour";
		EXPECT_NEAR(pairs[n].distance_m, 0, 1e-12);
	}
}

TEST(Revisit, IdenticalTrajectoryHasZeroError)
{
	const Trajectory gt = squareCircuit(kOneAndAHalfLaps);
	const RevisitResult r = computeRevisitError(gt, gt, kCircuit);
	EXPECT_EQ(r.pairs.size(), kCircuitPairs);
	EXPECT_NEAR(r.t_rmse_m, 0, 1e-9);
	EXPECT_NEAR(r.t_max_m, 0, 1e-9);
	EXPECT_NEAR(r.r_rmse_deg, 0, 1e-6);
	EXPECT_NEAR(r.r_max_deg, 0, 1e-6);
}

TEST(Revisit, PositionOffsetAfterTheFirstLapIsTheTranslationError)
{
	// From the second lap on, the estimate is 0.5 m off: a pair across the laps has the error
	// G_j^-1 D G_j, whose translation is R_j^T d (0.5 m) and rotation none; the two pairs inside the first
	// lap have none. So RMS = 0.5 sqrt(201 / 203), max 0.5.
	const Trajectory gt = squareCircuit(kOneAndAHalfLaps);
	Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
	D.translation() = Eigen::Vector3d(0.3, -0.4, 0);
	const RevisitResult r = computeRevisitError(gt, movedFrom(gt, kLap, D), kCircuit);
	ASSERT_EQ(r.pairs.size(), kCircuitPairs);
	EXPECT_NEAR(r.t_rmse_m, 0.5 * std::sqrt(201.0 / 203.0), 1e-9);
	EXPECT_NEAR(r.t_max_m, 0.5, 1e-9);
	EXPECT_NEAR(r.r_max_deg, 0, 1e-6);
}

TEST(Revisit, YawDriftAfterTheFirstLapGivesTheChordOfEachPlace)
{
	// From the second lap on, the estimate is turned by theta about the start: the error of a pair across the
	// laps has the rotation theta and the translation |(R_theta - I)(p_j - start)| = 2 sin(theta/2) |p_j - start|.
	// The second lap's poses 400..600 lie on the first two sides: |p - start|^2 = m^2 (m = 0..100), then
	// 100^2 + m^2 (m = 1..100), summing to 2 * 338350 + 1e6 = 1676700 over the 203 pairs (2 of them exact).
	const double theta = 0.5 * kRadPerDeg;
	const Trajectory gt = squareCircuit(kOneAndAHalfLaps);
	Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
	D.linear() = Rz(theta);
	D.translation() = kStart - Rz(theta) * kStart;  // about the start
	const RevisitResult r = computeRevisitError(gt, movedFrom(gt, kLap, D), kCircuit);
	ASSERT_EQ(r.pairs.size(), kCircuitPairs);
	const double chord = 2 * std::sin(theta / 2);
	EXPECT_NEAR(r.t_rmse_m, chord * std::sqrt(1676700.0 / 203.0), 1e-9);  // 0.7931 m
	EXPECT_NEAR(r.t_max_m, chord * std::sqrt(2) * kSide, 1e-9);  // the far corner
	EXPECT_NEAR(r.r_rmse_deg, 0.5 * std::sqrt(201.0 / 203.0), 1e-7);
	EXPECT_NEAR(r.r_max_deg, 0.5, 1e-7);
}

TEST(Revisit, StraightDriveHasNone)
{
	const Trajectory gt = fromSteps(1000, arcStep(1.0, 0));  // 999 m straight, neighbours 1 m apart
	EXPECT_TRUE(findRevisits(gt).empty());
	const RevisitResult r = computeRevisitError(gt, scaled(gt, 1.1));
	EXPECT_TRUE(r.empty());
	EXPECT_EQ(r.t_rmse_m, 0);
}

TEST(Revisit, OppositeDirectionIsARevisit)
{
	// Back along the lane 2 m beside the way out: return pose x = k pairs with the way out's x = k when the
	// path between them, 2 (100 - k) + 3 (the U-turn's three 1 m chords), is at least 50 m: k = 0..76, 77 pairs. Their relative pose turns
	// by 180 deg. With the way back 0.5 m off, each error is 0.5 m.
	const Trajectory gt = outAndBack();
	const RevisitOptions o{2.1, 50};  // 2 m across, not 2.24 m to the neighbours
	const auto pairs = findRevisits(gt, o);
	ASSERT_EQ(pairs.size(), 77u);
	for (const auto& p : pairs)
	{
		const double x = gt[p.second].pose.translation().x();
		EXPECT_EQ(p.first, std::size_t(std::lround(x))) << "return pose " << p.second;
		EXPECT_NEAR(p.distance_m, 2, 1e-12);
		EXPECT_NEAR(rotationAngle((gt[p.first].pose.inverse() * gt[p.second].pose).linear()), M_PI, 1e-9);
	}
	EXPECT_EQ(pairs.front().second, 103u + 24u);  // x = 76
	EXPECT_EQ(pairs.back().second, gt.size() - 1);  // x = 0
	Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
	D.translation() = Eigen::Vector3d(0, 0.5, 0);
	const RevisitResult r = computeRevisitError(gt, movedFrom(gt, 101, D), o);
	EXPECT_NEAR(r.t_rmse_m, 0.5, 1e-9);
	EXPECT_NEAR(r.t_max_m, 0.5, 1e-9);
	EXPECT_NEAR(r.r_max_deg, 0, 1e-6);
}

TEST(Revisit, GridFindsWhatComparingEveryPairFinds)
{
	// A 3D drive around a 10 m circle, up and down, three times (wiggly: 0.1 s, ~0.1 m apart), negative
	// coordinates included: the cubes must give each pose the same nearest earlier revisit as a search of all.
	const Trajectory gt = wiggly(2000);
	const RevisitOptions o{0.7, 20};
	const std::vector<double> dist = trajectoryDistances(gt);
	std::vector<RevisitPair> expected;
	for (std::size_t j = 0; j < gt.size(); ++j)
	{
		RevisitPair best{0, j, INFINITY, 0, 0};
		for (std::size_t i = 0; i < j; ++i)
		{
			const double d = (gt[i].pose.translation() - gt[j].pose.translation()).norm();
			if (dist[j] - dist[i] >= o.min_path_m && d <= o.radius_m && d < best.distance_m) best.first = i, best.distance_m = d;
		}
		if (std::isfinite(best.distance_m)) expected.push_back(best);
	}
	const auto pairs = findRevisits(gt, o);
	ASSERT_GT(expected.size(), 100u);
	ASSERT_EQ(pairs.size(), expected.size());
	for (std::size_t n = 0; n < pairs.size(); ++n)
	{
		EXPECT_EQ(pairs[n].first, expected[n].first) << n;
		EXPECT_EQ(pairs[n].second, expected[n].second) << n;
	}
}

TEST(Revisit, RadiusMustBePositive)
{
	const Trajectory gt = squareCircuit(10);
	EXPECT_THROW(findRevisits(gt, {0, 50}), std::invalid_argument);
	EXPECT_THROW(findRevisits(gt, {NAN, 50}), std::invalid_argument);
}

TEST(Revisit, EvaluateReportsItByTimeAndSaysWhenThereIsNone)
{
	// The estimate at 20 Hz, the ground truth at 10 Hz: association interpolates the truth at each estimated
	// pose, so the revisits are those of the matched poses (twice as many) and the offset is the error.
	const Trajectory gt = squareCircuit(kOneAndAHalfLaps);
	Trajectory dense;
	for (std::size_t k = 0; k + 1 < gt.size(); ++k)
		for (int h = 0; h < 2; ++h)
			dense.push_back({gt[k].t + 0.05 * h, interpolate(gt[k].pose, gt[k + 1].pose, 0.5 * h)});
	Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
	D.translation() = Eigen::Vector3d(0.3, -0.4, 0);
	EvalOptions o;
	o.revisit_options = {0.6, 50};  // the same place only (neighbours are 0.5 m apart)
	EvalReport r = evaluate(gt, movedFrom(dense, 2 * kLap, D), o);
	ASSERT_TRUE(r.revisit.has_value());
	EXPECT_EQ(r.revisit->pairs.size(), 401u);  // 800..1199 with 0..399, and 799 (0.5 m before the start) with 0
	EXPECT_NEAR(r.revisit->t_max_m, 0.5, 1e-9);
	std::string j = toJson(r);
	EXPECT_NE(j.find("\"revisit_pairs\": 401,"), std::string::npos) << j;
	EXPECT_NEAR(jsonNumber(j, "revisit_t_rmse_m"), 0.5 * std::sqrt(400.0 / 401.0), 1e-9) << j;
	EXPECT_NEAR(jsonNumber(j, "revisit_t_max_m"), 0.5, 1e-9) << j;
	EXPECT_NEAR(jsonNumber(j, "revisit_r_rmse_deg"), 0, 1e-6) << j;
	EXPECT_NE(j.find("\"revisit_radius_m\": 0.6,"), std::string::npos) << j;
	EXPECT_NE(j.find("\"revisit_note\": null"), std::string::npos) << j;
	EXPECT_NE(j.find("\"metric\": \"all\""), std::string::npos) << j;
	std::string table = formatTable(r);
	EXPECT_NE(table.find("  Revisit error, translation  0.4994 m RMS, 0.5000 m max  (401 pairs: within 0.6 m after >= 50 m of path)\n"),
		std::string::npos)
		<< table;

	const Trajectory line = fromSteps(1000, arcStep(1.0, 0));
	r = evaluate(line, line, EvalOptions{});
	ASSERT_TRUE(r.revisit.has_value());
	EXPECT_TRUE(r.revisit->empty());
	j = toJson(r);
	EXPECT_NE(j.find("\"revisit_pairs\": 0,"), std::string::npos) << j;
	EXPECT_NE(j.find("\"revisit_t_rmse_m\": null,"), std::string::npos) << j;
	EXPECT_NE(j.find("\"revisit_note\": \"no revisit: the ground truth never comes back within 3 m of a place after at least 50 m of path\""),
		std::string::npos)
		<< j;
	EXPECT_NE(formatTable(r).find("  Revisit error               no revisit (0 pairs: within 3 m after >= 50 m of path)\n"),
		std::string::npos)
		<< formatTable(r);
}

TEST(Revisit, OtherMetricsAloneLeaveItOutOfTheTable)
{
	const Trajectory gt = squareCircuit(kOneAndAHalfLaps);
	EvalOptions o;
	parseMetric("ate", o);
	EvalReport r = evaluate(gt, gt, o);
	EXPECT_FALSE(r.revisit.has_value());
	EXPECT_EQ(formatTable(r).find("Revisit"), std::string::npos);
	EXPECT_NE(toJson(r).find("\"revisit_note\": \"not requested (--metric)\""), std::string::npos);
	parseMetric("revisit", o);
	EXPECT_FALSE(o.ate || o.kitti || o.rpe);
	r = evaluate(gt, gt, o);
	ASSERT_TRUE(r.revisit.has_value());
	EXPECT_EQ(r.revisit->pairs.size(), 204u);  // the default 3 m radius adds pose 397 (3 m from the start)
	EXPECT_NE(toJson(r).find("\"metric\": \"revisit\""), std::string::npos);
	o.gt_translation_only = true;
	r = evaluate(gt, gt, o);
	EXPECT_FALSE(r.revisit.has_value());
	EXPECT_NE(formatTable(r).find("Revisit error               n/a: needs full ground-truth poses"), std::string::npos);
}
