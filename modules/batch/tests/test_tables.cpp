#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <vlo/batch/jobs.h>
#include <vlo/batch/json_fields.h>
#include <vlo/batch/results.h>
#include <vlo/batch/snapshots.h>
#include <vlo/batch/tables.h>
#include <vlo/core/error.h>

#include <cmath>
#include <fstream>

using namespace vlo;
using namespace vlo::batch;
namespace fs = std::filesystem;

namespace
{
std::string evalJson(const std::string& ate, const std::string& are, const std::string& t, const std::string& r,
	const std::string& revisit = "")
{
	// The layout of vlo-eval --json (modules/eval/src/report.cpp), nested array included.
	return "{\n" + revisit + "  \"gt\": \"a \\\"b\\\".tum\",\n  \"n_matched\": 25,\n  \"gt_length_m\": 31.5,\n  \"ate_rmse_m\": " + ate +
		",\n  \"are_rmse_deg\": " + are + ",\n  \"sim3_scale\": 0.98,\n  \"ate_note\": null,\n  \"kitti_t_err_pct\": " + t +
		",\n  \"kitti_r_err_deg_per_m\": " + r + ",\n  \"kitti_segments\": 12,\n  \"kitti_per_length\": [\n    {\"length_m\": 10, "
												 "\"segments\": 6, \"t_err_pct\": 1.5}\n  ],\n  \"kitti_note\": null\n}\n";
}

const std::string kTum = "0 0 0 0 0 0 0 1\n0.1 1 0 0 0 0 0 1\n0.2 2 0.1 0 0 0 0 1\n";

/// Two sequences (the second with translation-only ground truth) x four configurations, as runs
/// leave them: ok, a failed evaluation, a failed vlo-run, and never run.
struct BatchTables : public ::testing::Test
{
	test::ScratchDir dir{"tables"};
	std::string out = dir / "out";
	Plan plan;
	void SetUp() override
	{
		plan.source = "ini/experiments/t.ini";
		plan.data_dir = dir / "data";
		plan.kitti_lengths = "10,20";
		for (const char* s : {"s1", "s2"})
		{
			Sequence q;
			q.name = s;
			q.gt = dir / (std::string("data/") + s + ".gt.tum");
			q.gt_translation_only = q.name == "s2";
			test::writeFile(q.gt, kTum);
			plan.sequences.push_back(q);
		}
		plan.configs = {{"lo", {"pipeline.mode=lo"}, "se3", ""}, {"vo_mono", {"pipeline.mode=vo"}, "sim3", ""},
			{"broken", {"x.y=1"}, "se3", ""}, {"later", {}, "se3", ""}};
		const auto run = [&](const std::string& s, const std::string& c) { return runDir(out, s, c) + "/"; };
		for (const auto& [s, ms] : {std::pair<std::string, double>{"s1", 20.0}, {"s2", 30.0}})
		{
			test::writeFile(run(s, "lo") + "exit_code", "0\n");
			test::writeFile(run(s, "lo") + "summary.json",
				"{\"mode\": \"lo\", \"frames\": 25, \"ms_per_frame\": " + std::to_string(ms) + "}\n");
			test::writeFile(run(s, "lo") + "trajectory_lo.tum", kTum);
			test::writeFile(run(s, "broken") + "exit_code", "2\n");
			test::writeFile(run(s, "broken") + "vlo-run.err", "a warning\nvlo-run: error: x.ini: unknown key 'y' | in [x]\n");
		}
		test::writeFile(run("s1", "lo") + "eval_lo.json", evalJson("0.5", "0.3", "1.25", "0.0042"));
		test::writeFile(run("s2", "lo") + "eval_lo.json", evalJson("0.456", "null", "null", "null"));
		test::writeFile(run("s1", "vo_mono") + "exit_code", "0\n");
		test::writeFile(run("s1", "vo_mono") + "summary.json", "{\"ms_per_frame\": 50}\n");
		test::writeFile(run("s1", "vo_mono") + "trajectory_vo.tum", kTum);
		test::writeFile(run("s1", "vo_mono") + "aligned_vo.tum", kTum);
		test::writeFile(run("s1", "vo_mono") + "eval_vo.json", evalJson("0.789", "1.23", "40", "0.1"));
		test::writeFile(run("s2", "vo_mono") + "exit_code", "1\n");
		test::writeFile(run("s2", "vo_mono") + "summary.json", "{\"ms_per_frame\": 60}\n");
		test::writeFile(run("s2", "vo_mono") + "trajectory_vo.tum", kTum);
		test::writeFile(run("s2", "vo_mono") + "eval_vo.err", "vlo-eval: error: too few poses\n");
	}
	bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
};
}  // namespace

TEST_F(BatchTables, CollectsStatusErrorsAndNumbers)
{
	const auto rs = collectResults(plan, out);
	ASSERT_EQ(rs.size(), 8u);
	EXPECT_EQ(rs[0].status, RunStatus::Ok);
	EXPECT_DOUBLE_EQ(rs[0].ms_per_frame, 20.0);
	EXPECT_DOUBLE_EQ(rs[0].frames, 25.0);
	ASSERT_EQ(rs[0].trajectories.size(), 1u);
	EXPECT_DOUBLE_EQ(rs[0].trajectories[0].eval.number("kitti_t_err_pct"), 1.25);
	EXPECT_EQ(rs[1].trajectories[0].aligned, runDir(out, "s1", "vo_mono") + "/aligned_vo.tum");
	EXPECT_EQ(rs[2].status, RunStatus::Failed);
	EXPECT_EQ(rs[2].error, "vlo-run: error: x.ini: unknown key 'y' | in [x]");  // the error line, not the warning
	EXPECT_EQ(rs[3].status, RunStatus::Missing);
	EXPECT_EQ(rs[3].error, "not run");
	EXPECT_EQ(rs[5].status, RunStatus::Failed);
	EXPECT_EQ(rs[5].trajectories[0].error, "vlo-eval: error: too few poses");
	EXPECT_EQ(rs[5].error, "trajectory_vo.tum: vlo-eval: error: too few poses");
	// A damaged JSON file fails its own row, not the collection.
	test::writeFile(runDir(out, "s1", "lo") + "/eval_lo.json", "{\"ate_rmse_m\": ");
	const auto damaged = collectRun(runDir(out, "s1", "lo"), plan.sequences[0], plan.configs[0]);
	ASSERT_EQ(damaged.trajectories.size(), 1u);
	const std::string& why = damaged.trajectories[0].error;
	EXPECT_NE(why.find("eval_lo.json: not valid JSON"), std::string::npos) << why;
	fs::create_directories(runDir(out, "s9", "x"));
	EXPECT_EQ(collectRun(runDir(out, "s9", "x"), plan.sequences[0], plan.configs[0]).error, "did not finish (no exit_code)");
}

TEST_F(BatchTables, MarkdownHasThePaperTables)
{
	const auto md = markdownResults(plan, collectResults(plan, out), {"snapshots/s1.png"});
	EXPECT_TRUE(has(md, "Sequences: 2, configurations: 4, runs: 8 (3 done, 3 failed, 2 not run).")) << md;
	EXPECT_TRUE(has(md, "| configuration / trajectory | align | s1 | s2 | mean |\n|---|---|---:|---:|---:|\n")) << md;
	EXPECT_TRUE(has(md, "| vo_mono / vo | sim3 | 0.789 / 1.23 | failed | – |\n")) << md;
	EXPECT_TRUE(has(md, "segments of 10,20 m")) << md;
	EXPECT_TRUE(has(md, "| lo / lo | 1.25 / 0.0042 | ATE 0.456 m | – |\n")) << md;
	EXPECT_TRUE(has(md, "| broken | failed | failed | – |\n")) << md;
	EXPECT_TRUE(has(md, "| later | not run | not run | – |\n")) << md;
	EXPECT_TRUE(has(md, "| lo | 20.0 | 30.0 | 25.0 |\n")) << md;  // timing, with the mean
	EXPECT_TRUE(has(md, "| vo_mono | 50.0 | 60.0 | 55.0 |\n")) << md;
	EXPECT_TRUE(has(md, "| s1 / broken | vlo-run: error: x.ini: unknown key 'y' \\| in [x] |\n")) << md;
	EXPECT_TRUE(has(md, "| s2 / vo_mono (vo) | vlo-eval: error: too few poses |\n")) << md;
	EXPECT_TRUE(has(md, "![snapshots/s1.png](snapshots/s1.png)")) << md;
	EXPECT_FALSE(has(md, "vo_mono / lo"));
	EXPECT_FALSE(has(md, "Revisits")) << "no drive comes back to a place: no revisit table";
}

TEST_F(BatchTables, LoopClosedTrajectoryBesideTheOdometryWithTheRevisitError)
{
	// s1/lo also left trajectory_slam.tum (loop closure on); s1 comes back to its places, s2 does not.
	const auto revisit = [](const char* pairs, const char* t_rmse) {
		return std::string("  \"revisit_pairs\": ") + pairs + ",\n  \"revisit_t_rmse_m\": " + t_rmse +
			",\n  \"revisit_t_max_m\": 0.7,\n  \"revisit_r_rmse_deg\": 0.25,\n  \"revisit_r_max_deg\": 0.5,\n";
	};
	test::writeFile(runDir(out, "s1", "lo") + "/eval_lo.json", evalJson("0.5", "0.3", "1.25", "0.0042", revisit("204", "0.4963")));
	test::writeFile(runDir(out, "s1", "lo") + "/trajectory_slam.tum", kTum);
	test::writeFile(runDir(out, "s1", "lo") + "/eval_slam.json", evalJson("0.12", "0.1", "0.5", "0.001", revisit("204", "0.031")));
	test::writeFile(runDir(out, "s2", "lo") + "/eval_lo.json", evalJson("0.456", "null", "null", "null", revisit("0", "null")));
	const auto rs = collectResults(plan, out);
	ASSERT_EQ(rs[0].trajectories.size(), 2u);
	EXPECT_EQ(rs[0].trajectories[0].name, "lo");
	EXPECT_EQ(rs[0].trajectories[1].name, "slam");
	EXPECT_DOUBLE_EQ(rs[0].trajectories[1].eval.number("revisit_t_rmse_m"), 0.031);
	EXPECT_TRUE(trajectoryBefore("vlo", "slam")) << "the loop-closed trajectory after its odometry's";
	EXPECT_TRUE(trajectoryBefore("lo", "vlo"));
	EXPECT_FALSE(trajectoryBefore("slam", "vlo"));

	const auto md = markdownResults(plan, rs, {});
	EXPECT_TRUE(has(md, "| lo / lo | 1.25 / 0.0042 | ATE 0.456 m | – |\n| lo / slam | 0.50 / 0.0010 | – | – |\n")) << md;
	EXPECT_TRUE(has(md, "## Revisits: ATE / revisit error\n")) << md;
	EXPECT_TRUE(has(md, "places within 3 m after at least 50 m of path")) << md;
	EXPECT_TRUE(has(md, "| lo / lo | 0.500 / 0.496 | 0.456 / no revisit | – |\n| lo / slam | 0.120 / 0.031 | – | – |\n")) << md;
	EXPECT_TRUE(has(md, "| broken | failed | failed | – |\n| later | not run | not run | – |\n\n## Timing")) << md;
	EXPECT_FALSE(has(md, "vo_mono / vo | 0.789")) << "the visual odometry stays in its own table";
	plan.revisit_radius = 2.5;
	EXPECT_TRUE(has(markdownResults(plan, rs, {}), "places within 2.5 m after at least 50 m")) << md;

	const auto csv = csvResults(rs);
	EXPECT_TRUE(has(csv, "\ns1,lo,lo,ok,se3,0.5,0.3,0.98,1.25,0.0042,12,,,25,31.5,204,0.4963,0.7,0.25,0.5,,25,20,\n"
						 "s1,lo,slam,ok,se3,0.12,0.1,0.98,0.5,0.001,12,,,25,31.5,204,0.031,0.7,0.25,0.5,,25,20,\n"))
		<< csv;
	EXPECT_TRUE(has(csv, "\ns2,lo,lo,ok,se3,0.456,,0.98,,,12,,,25,31.5,0,,0.7,0.25,0.5,,25,30,\n")) << csv;
}

TEST_F(BatchTables, MeanOverSequencesWhenAllHaveNumbers)
{
	test::writeFile(runDir(out, "s2", "lo") + "/eval_lo.json", evalJson("0.2", "0.1", "0.75", "0.0022"));
	const auto md = markdownResults(plan, collectResults(plan, out), {});
	EXPECT_TRUE(has(md, "| lo / lo | 1.25 / 0.0042 | 0.75 / 0.0022 | 1.00 / 0.0032 |\n")) << md;
}

TEST_F(BatchTables, CsvHasEveryNumber)
{
	const auto csv = csvResults(collectResults(plan, out));
	EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
	EXPECT_EQ(csv.substr(0, csv.find('\n')),
		"sequence,config,trajectory,status,align,ate_rmse_m,are_rmse_deg,sim3_scale,kitti_t_err_pct,kitti_r_err_deg_per_m,"
		"kitti_segments,rpe_t_rmse_m,rpe_r_rmse_deg,n_matched,gt_length_m,revisit_pairs,revisit_t_rmse_m,revisit_t_max_m,"
		"revisit_r_rmse_deg,revisit_r_max_deg,path_ratio,frames,ms_per_frame,error");
	EXPECT_TRUE(has(csv, "\ns1,lo,lo,ok,se3,0.5,0.3,0.98,1.25,0.0042,12,,,25,31.5,,,,,,,25,20,\n")) << csv;
	EXPECT_TRUE(has(csv, "\ns2,lo,lo,ok,se3,0.456,,0.98,,,12,,,25,31.5,,,,,,,25,30,\n")) << csv;
	EXPECT_TRUE(has(csv, "\ns1,broken,,failed,se3,,,,,,,,,,,,,,,,,,,vlo-run: error: x.ini: unknown key 'y' | in [x]\n")) << csv;
	EXPECT_TRUE(has(csv, "\ns2,vo_mono,vo,failed,sim3,,,,,,,,,,,,,,,,,,60,vlo-eval: error: too few poses\n")) << csv;
	EXPECT_TRUE(has(csv, "\ns1,later,,not run,se3,,,,,,,,,,,,,,,,,,,not run\n")) << csv;
}

TEST_F(BatchTables, SnapshotPerSequenceWithTrajectories)
{
	const auto pngs = writeSnapshots(plan, collectResults(plan, out), out);
	const std::vector<std::string> expected{"snapshots/s1.png", "snapshots/s2.png"};
	EXPECT_EQ(pngs, expected);
	for (const auto& p : pngs) EXPECT_GT(fs::file_size(out + "/" + p), 1000u);
}

TEST_F(BatchTables, SnapshotLeavesOutARunsCopyOfItsOwnTrajectory)
{
	// s1's lo run closed no loop: its trajectory_slam.tum is its trajectory_lo.tum; s2's closed one.
	test::writeFile(runDir(out, "s1", "lo") + "/trajectory_slam.tum", kTum);
	test::writeFile(runDir(out, "s2", "lo") + "/trajectory_slam.tum", "0 0 0 0 0 0 0 1\n0.1 1 0 0 0 0 0 1\n0.2 2 0 0 0 0 0 1\n");
	const auto rs = collectResults(plan, out);
	const auto names = [&rs](const Sequence& s) {
		std::vector<std::string> n;
		for (const auto& t : sequenceTrajectories(s, rs)) n.push_back(t.name);
		return n;
	};
	// s1's vo_mono trajectory equals its lo one too, but it is another run's: drawn.
	EXPECT_EQ(names(plan.sequences[0]), (std::vector<std::string>{"lo / lo", "vo_mono / vo (Sim(3) aligned)"}));
	EXPECT_EQ(names(plan.sequences[1]), (std::vector<std::string>{"lo / lo", "lo / slam", "vo_mono / vo"}));
}

TEST(BatchJson, ScalarsStringsAndNulls)
{
	const auto j = JsonFields::parse("{\"a\": 1.5e2, \"b\": null, \"s\": \"x \\\"y\\\"\\n\", \"arr\": [1, {\"c\": \"]\"}], \"o\": {}, "
									 "\"t\": true}",
		"j");
	EXPECT_DOUBLE_EQ(j.number("a"), 150.0);
	EXPECT_TRUE(std::isnan(j.number("b")));
	EXPECT_TRUE(std::isnan(j.number("missing")));
	EXPECT_EQ(j.text("s"), "x \"y\"\n");
	EXPECT_FALSE(j.has("arr"));
	EXPECT_EQ(j.text("t"), "true");
	EXPECT_THROW(JsonFields::parse("[1]", "j"), InputError);
	EXPECT_THROW(JsonFields::parse("{\"a\": 1", "j"), InputError);
	EXPECT_THROW(JsonFields::read("/no/such.json"), InputError);
}

TEST(BatchJson, CorruptFileIsOneLineNamingIt)
{
	const std::string path = "corrupt_summary.json";
	std::ofstream(path) << "{\"frames\": 12,\n\"ms_per_frame\": 3.\n";
	try
	{
		JsonFields::read(path);
		FAIL() << "no error";
	}
	catch (const InputError& e)
	{
		const std::string m = e.what();
		EXPECT_EQ(m.rfind(path + ": not valid JSON (", 0), 0u) << m;
		EXPECT_EQ(m.find('\n'), std::string::npos) << m;
	}
}
