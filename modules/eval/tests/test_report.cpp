#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/eval/camera_frame.h>
#include <vlo/eval/evaluate.h>
#include <vlo/eval/report.h>

#include <cstdio>
#include <fstream>

#include "eval_test_utils.h"

using namespace vlo;
using namespace vlo::eval;
using namespace vlo::test;

namespace
{
bool hasKey(const std::string& json, const std::string& key) { return json.find("\"" + key + "\": ") != std::string::npos; }

/// The raw value text of a top-level key (up to the comma or newline).
std::string value(const std::string& json, const std::string& key)
{
	const auto p = json.find("\"" + key + "\": ");
	if (p == std::string::npos) return "<missing>";
	const auto b = p + key.size() + 4;
	return json.substr(b, json.find_first_of(",\n", b) - b);
}

const EvalOptions kDefaults;
const char* kRequired[] = {"kitti_t_err_pct", "kitti_r_err_deg_per_m", "ate_rmse_m", "are_rmse_deg", "sim3_scale", "n_matched"};
}  // namespace

TEST(Evaluate, LongIdenticalTrajectoriesScoreZeroEverywhere)
{
	const Trajectory gt = fromSteps(1500, arcStep(0.9, 0.002));  // 1349 m of gentle curve
	const EvalReport r = evaluate(gt, gt, kDefaults);
	const std::string j = toJson(r);
	for (const char* k : kRequired) EXPECT_TRUE(hasKey(j, k)) << k;
	EXPECT_EQ(value(j, "n_matched"), "1500");
	EXPECT_NEAR(std::stod(value(j, "ate_rmse_m")), 0, 1e-9);
	EXPECT_NEAR(std::stod(value(j, "are_rmse_deg")), 0, 1e-5);
	EXPECT_NEAR(std::stod(value(j, "kitti_t_err_pct")), 0, 1e-9);
	EXPECT_NEAR(std::stod(value(j, "kitti_r_err_deg_per_m")), 0, 1e-7);
	EXPECT_NEAR(std::stod(value(j, "sim3_scale")), 1, 1e-9);
	EXPECT_NEAR(std::stod(value(j, "path_ratio")), 1, 1e-12);
	EXPECT_EQ(value(j, "kitti_note"), "null");
	const auto per_length = j.find("\"kitti_per_length\": [");
	ASSERT_NE(per_length, std::string::npos);
	EXPECT_LT(j.find("\"length_m\": 100", per_length), j.find("]", per_length));  // the first entry is 100 m
	EXPECT_EQ(j.find("nan"), std::string::npos);
	EXPECT_NE(formatTable(r).find("KITTI t_err"), std::string::npos);
}

TEST(Evaluate, ShortTrajectoryReportsNullKittiWithTheReason)
{
	const Trajectory gt = fromSteps(50, arcStep(0.9, 0.01));
	const EvalReport r = evaluate(gt, scaled(gt, 1.1), kDefaults);
	ASSERT_TRUE(r.kitti.has_value());
	EXPECT_TRUE(r.kitti->empty());
	const std::string j = toJson(r);
	EXPECT_EQ(value(j, "kitti_t_err_pct"), "null");
	EXPECT_EQ(value(j, "kitti_r_err_deg_per_m"), "null");
	EXPECT_EQ(value(j, "kitti_segments"), "0");
	EXPECT_NE(j.find("\"kitti_note\": \"no segment: the ground-truth path over the matched poses is 44.1 m, not longer than the shortest segment length (100 m)\""), std::string::npos) << j;
	EXPECT_NE(value(j, "ate_rmse_m"), "null");
	EXPECT_NE(formatTable(r).find("n/a: no segment"), std::string::npos);
}

TEST(Evaluate, MetricSelectionAndTranslationOnlyGroundTruth)
{
	const Trajectory est = fromSteps(200, arcStep(0.9, 0.01));
	EvalOptions o;
	parseMetric("kitti", o);
	std::string j = toJson(evaluate(est, est, o));
	EXPECT_EQ(value(j, "ate_rmse_m"), "null");
	EXPECT_EQ(value(j, "sim3_scale"), "null");
	EXPECT_EQ(value(j, "rpe_t_rmse_m"), "null");
	EXPECT_THROW(parseMetric("speed", o), InputError);

	Trajectory gt = est;
	for (auto& p : gt) p.pose.linear().setIdentity();
	o = EvalOptions();
	o.gt_translation_only = true;
	j = toJson(evaluate(gt, est, o));
	EXPECT_NEAR(std::stod(value(j, "ate_rmse_m")), 0, 1e-9);
	EXPECT_EQ(value(j, "are_rmse_deg"), "null");
	EXPECT_EQ(value(j, "kitti_t_err_pct"), "null");
	EXPECT_EQ(value(j, "kitti_segments"), "null");
	EXPECT_NE(value(j, "kitti_note").find("translation-only"), std::string::npos);
	EXPECT_EQ(value(j, "gt_translation_only"), "true");
}

TEST(Evaluate, OneHertzGroundTruthAgainstTenHertzEstimate)
{
	// The same straight 10 Hz drive; the ground truth keeps only every 10th pose.
	const Trajectory est = fromSteps(2001, arcStep(0.9, 0));
	Trajectory gt;
	for (std::size_t i = 0; i < est.size(); i += 10) gt.push_back(est[i]);
	const EvalReport r = evaluate(gt, scaled(est, 1.05), kDefaults);
	EXPECT_EQ(r.association.matched(), est.size());
	EXPECT_NEAR(r.association.max_gap_used_s, 3.0, 1e-9);
	EXPECT_NEAR(*r.ate->sim3_scale, 1 / 1.05, 1e-12);
	ASSERT_TRUE(r.kitti && !r.kitti->empty());
	EXPECT_NEAR(r.kitti->per_length[0].t_err, 0.05 * 1.008, 1e-9);  // segments over the 10 Hz frames
}

TEST(Evaluate, NoOverlapInTimeIsAClearError)
{
	const Trajectory gt = fromSteps(50, arcStep(1, 0));
	Trajectory est = gt;
	for (auto& p : est) p.t += 100;
	EvalOptions o;
	o.gt_name = "gt.tum";
	o.est_name = "est.tum";
	try
	{
		evaluate(gt, est, o);
		FAIL() << "no error";
	}
	catch (const InputError& e)
	{
		const std::string m = e.what();
		EXPECT_EQ(m.rfind("est.tum: no pose overlaps the ground truth gt.tum in time", 0), 0u) << m;
	}
	est.resize(2);
	for (auto& p : est) p.t -= 100;
	EXPECT_THROW(evaluate(gt, est, o), InputError);  // 2 poses are not enough
}

TEST(Report, JsonIsWrittenAtomically)
{
	const Trajectory gt = fromSteps(20, arcStep(1, 0.1));
	const std::string path = "test_eval_report.json";
	std::remove(path.c_str());
	writeJson(path, evaluate(gt, gt, kDefaults));
	std::ifstream in(path);
	const std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	EXPECT_EQ(s.front(), '{');
	EXPECT_EQ(s.substr(s.size() - 2), "}\n");
	EXPECT_FALSE(std::ifstream(path + ".partial").good());
	std::remove(path.c_str());
	EXPECT_THROW(writeJson("/nonexistent-dir/x.json", evaluate(gt, gt, kDefaults)), InputError);
}

TEST(CameraFrame, ParsesTwelveNumbersAndKittiCalib)
{
	const Eigen::Isometry3d T = parseCam0TVehicle("0 -1 0 0.1, 0 0 -1 0.2, 1 0 0 0.3");
	EXPECT_EQ(T.translation(), Eigen::Vector3d(0.1, 0.2, 0.3));
	EXPECT_NEAR(T.linear().determinant(), 1, 1e-12);
	EXPECT_THROW(parseCam0TVehicle("1 0 0 0 0 1 0 0 0 0 1"), InputError);  // 11
	EXPECT_THROW(parseCam0TVehicle("2 0 0 0 0 1 0 0 0 0 1 0"), InputError);  // not a rotation
	EXPECT_THROW(parseCam0TVehicle("1 0 0 0 0 1 0 0 0 0 -1 0"), InputError);  // a reflection
	EXPECT_THROW(parseCam0TVehicle("1 0 0 x 0 1 0 0 0 0 1 0"), InputError);

	const std::string calib = "test_eval_calib.txt";
	std::ofstream(calib) << "P0: 1 0 0 0 0 1 0 0 0 0 1 0\nTr: 0 -1 0 0.1 0 0 -1 0.2 1 0 0 0.3\n";
	EXPECT_TRUE(readKittiCalibTr(calib).isApprox(T, 1e-12));
	std::ofstream(calib) << "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n";
	EXPECT_THROW(readKittiCalibTr(calib), InputError);
	std::remove(calib.c_str());
	EXPECT_THROW(readKittiCalibTr("no-such-calib.txt"), InputError);
}

TEST(Evaluate, GroundTruthOfAnotherDriveIsWarnedAbout)
{
	const Trajectory gt = fromSteps(200, arcStep(1.0, 0.02));
	EXPECT_TRUE(evaluate(gt, gt, kDefaults).warnings.empty());
	EXPECT_TRUE(evaluate(gt, scaled(gt, 1.3), kDefaults).warnings.empty());  // a poor estimate is no warning

	const auto warned = [&](const Trajectory& est, const EvalOptions& o, const std::string& text) {
		const auto w = evaluate(gt, est, o).warnings;
		ASSERT_EQ(w.size(), 1u) << text;
		EXPECT_NE(w[0].find(text), std::string::npos) << w[0];
		EXPECT_NE(w[0].find("ground truth of this drive"), std::string::npos) << w[0];
	};
	Trajectory late = gt;  // three quarters after the ground truth ends
	for (auto& p : late) p.t += 15.0;
	warned(late, kDefaults, "50 of 200 estimated poses");
	Trajectory other = fromSteps(200, arcStep(1.0, -0.03));  // another drive: turning the other way, same times
	for (auto& p : other) p.pose.linear() = Rz(M_PI * 0.9) * p.pose.linear();
	warned(other, kDefaults, "rotation error");
	warned(scaled(gt, 0.1), kDefaults, "--align sim3");  // an unscaled VO against SE(3) alignment
	EvalOptions sim3 = kDefaults;
	sim3.align = Alignment::Sim3;
	EXPECT_TRUE(evaluate(gt, scaled(gt, 0.1), sim3).warnings.empty());
}

// path_ratio: the estimate's path over the truth's; on the table's path line too.
TEST(Evaluate, PathRatioIsTheEstimatesLengthOverTheTruths)
{
	const Trajectory gt = fromSteps(200, arcStep(1.0, 0.001));
	Trajectory est = gt;
	for (auto& p : est) p.pose.translation() *= 1.02;
	const EvalReport r = evaluate(gt, est, kDefaults);
	EXPECT_NEAR(std::stod(value(toJson(r), "path_ratio")), 1.02, 1e-9);
	EXPECT_NE(formatTable(r).find("(ratio 1.0200)"), std::string::npos) << formatTable(r);
}
