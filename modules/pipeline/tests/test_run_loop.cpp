// The run loop with fake modules registered by name: what runPipeline passes from the motion source
// to the LiDAR odometry, what the metric monocular VO does with the scale corrector's factors, and
// what lands in frames.csv and the trajectories. The fakes move the vehicle 0.5 m forward per frame.
#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/core/interrupt.h>
#include <vlo/io/trajectory.h>
#include <vlo/kernel/lidar_odometry.h>
#include <vlo/kernel/scale_correction.h>
#include <vlo/kernel/visual_odometry.h>
#include <vlo/pipeline/run.h>

#include "run_loop_fakes.h"
#include "small_drive.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace vlo;
using namespace vlo::pipeline;
using namespace vlo::kernel;
using namespace vlo::pipeline::fakes;

namespace
{
class RunLoop : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		seen = {};
		// One folder per test: ctest -j runs the tests of this file side by side.
		dir_ = std::filesystem::absolute(std::string("run_loop_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
		std::filesystem::remove_all(dir_);
		std::filesystem::create_directories(dir_);
		test::writeSmallDrive(dir_ + "/drive.rawlog", kFrames, test::smallRig());
	}
	void TearDown() override { std::filesystem::remove_all(dir_); }

	RunSummary run(const std::vector<std::string>& sets)
	{
		std::ofstream(dir_ + "/run.ini") << "[pipeline]\nvisual_odometry = fake_mono\nscale_correction = fake_scale\n"
											"lidar_odometry = fake_lidar\nsnapshots = false\nmap_every = 0\n";
		return runPipeline({dir_ + "/drive.rawlog", dir_ + "/run.ini", dir_ + "/out", sets, ""});
	}

	/// The message of the InputError the run stops with ("" when it does not).
	std::string runError(const std::vector<std::string>& sets)
	{
		try
		{
			run(sets);
		}
		catch (const InputError& e)
		{
			return e.what();
		}
		return "";
	}

	std::string out(const std::string& name) const { return dir_ + "/out/" + name; }
	std::string dir_;
};

std::vector<std::string> split(const std::string& line)
{
	std::vector<std::string> cells;
	std::stringstream ls(line);
	for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
	return cells;
}

std::vector<std::string> header(const std::string& csv)
{
	std::ifstream in(csv);
	std::string line;
	std::getline(in, line);
	return split(line);
}

/// Cells of one column of a CSV without quoted commas (the fakes write none).
std::vector<std::string> column(const std::string& csv, const std::string& name)
{
	const auto names = header(csv);
	const auto at = std::find(names.begin(), names.end(), name) - names.begin();
	EXPECT_LT(std::size_t(at), names.size()) << "no column " << name;
	std::ifstream in(csv);
	std::string line;
	std::getline(in, line);
	std::vector<std::string> cells;
	while (std::getline(in, line))
	{
		std::stringstream ls(line);
		std::string c;
		for (long k = 0; k <= at; ++k) std::getline(ls, c, ',');
		cells.push_back(c);
	}
	return cells;
}
}  // namespace

TEST_F(RunLoop, MetricMonoVoGivesTheLidarOdometryTheScaledMotionInVehicleAxes)
{
	const RunSummary s = run({"pipeline.mode=vlo"});
	EXPECT_EQ(s.frames, std::size_t(kFrames));
	// The corrector sees the previous frame (none at the first); its decisions reach the VO, not the loop.
	EXPECT_EQ(seen.scale_prev_index, (std::vector<long>{-1, 0, 1, 2, 3, 4}));
	ASSERT_EQ(seen.rescales.size(), 2u);
	EXPECT_EQ(seen.rescales[0], std::make_pair(0.5, true));
	EXPECT_EQ(seen.rescales[1], std::make_pair(1.1, false));
	// Guesses: none before the first scale; then 0.5 m along the vehicle's x (camera z; the lever
	// arm cancels), 1.1 x 0.5 m from the correction on.
	ASSERT_EQ(seen.lidar_guesses.size(), std::size_t(kFrames));
	EXPECT_FALSE(seen.lidar_guesses[0]);
	EXPECT_FALSE(seen.lidar_guesses[1]);
	const double expected[] = {0, 0, 0.5, 0.5, 0.55, 0.55};
	for (int i = 2; i < kFrames; ++i)
	{
		ASSERT_TRUE(seen.lidar_guesses[i]) << i;
		EXPECT_NEAR(seen.lidar_guesses[i]->motion.translation().x(), expected[i], 1e-12) << i;
		EXPECT_NEAR(seen.lidar_guesses[i]->motion.translation().norm(), expected[i], 1e-12) << i;
		// Its quality: the VO's tracked features and the scale estimate's error of the same frame.
		EXPECT_EQ(seen.lidar_guesses[i]->quality.tracked, 40 + i) << i;
		EXPECT_DOUBLE_EQ(seen.lidar_guesses[i]->quality.length_error, 0.01 * i) << i;
	}
	EXPECT_EQ(column(out("frames.csv"), "vo_metric_motion"), (std::vector<std::string>{"0", "0", "1", "1", "1", "1"}));
	EXPECT_EQ(column(out("frames.csv"), "x"), (std::vector<std::string>{"0.000", "0.500", "1.000", "1.500", "2.000", "2.500"}));
	EXPECT_EQ(column(out("frames.csv"), "lo_fake"), std::vector<std::string>(kFrames, "3"));
	// The scale-corrected VO: frames 1-2 re-expressed at the first scale, then chained.
	const Trajectory vo = io::readTum(out("trajectory_vo.tum"));
	ASSERT_EQ(vo.size(), 5u);
	const double voX[] = {0, 0.5, 1.0, 1.55, 2.1};
	for (int k = 0; k < 5; ++k) EXPECT_NEAR(vo[k].pose.translation().x(), voX[k], 1e-6) << k;
	EXPECT_EQ(io::readTum(out("trajectory_vlo.tum")).size(), std::size_t(kFrames));
	EXPECT_EQ(s.final_trajectory, "trajectory_vlo.tum");
	ASSERT_EQ(s.figures.size(), 1u);
	EXPECT_EQ(s.figures[0].first, "fake_figure");
}

TEST_F(RunLoop, BootstrappingOffLeavesTheLidarOdometryToItself)
{
	run({"pipeline.mode=vlo", "pipeline.bootstrapping=false"});
	ASSERT_EQ(seen.lidar_guesses.size(), std::size_t(kFrames));
	for (const auto& g : seen.lidar_guesses) EXPECT_FALSE(g);
	// The motion source still runs: its column says when a guess would have been there.
	EXPECT_EQ(column(out("frames.csv"), "vo_metric_motion"), (std::vector<std::string>{"0", "0", "1", "1", "1", "1"}));
}

// Loop closure without a revisit (3 m of straight road): the loop-closed trajectory is the odometry's,
// pose for pose. Mode vo has no LiDAR odometry to close loops over: no trajectory_slam.tum.
TEST_F(RunLoop, LoopClosureWithoutRevisitKeepsTheOdometrysPoses)
{
	const RunSummary lo = run({"pipeline.mode=lo", "pipeline.loop_closure=true"});
	EXPECT_EQ(lo.slam_trajectory, "trajectory_slam.tum");
	const Trajectory odometry = io::readTum(out("trajectory_lo.tum")), slam = io::readTum(out("trajectory_slam.tum"));
	ASSERT_EQ(slam.size(), std::size_t(kFrames));
	ASSERT_EQ(odometry.size(), slam.size());
	for (std::size_t i = 0; i < slam.size(); ++i)
	{
		EXPECT_EQ(slam[i].t, odometry[i].t);
		EXPECT_NEAR((slam[i].pose.translation() - odometry[i].pose.translation()).norm(), 0, 1e-9);
	}
	const std::vector<std::string> h = header(out("frames.csv"));
	EXPECT_NE(std::find(h.begin(), h.end(), "ms_loop"), h.end());
	std::ifstream summaryFile(out("summary.json"));
	const auto summary = nlohmann::json::parse(summaryFile);
	EXPECT_EQ(summary["trajectory_slam"], "trajectory_slam.tum");
	EXPECT_EQ(summary["loops_accepted"], 0);

	std::filesystem::remove_all(out(""));
	const RunSummary vo = run({"pipeline.mode=vo", "pipeline.loop_closure=true", "pipeline.visual_odometry=fake_stereo"});
	EXPECT_TRUE(vo.slam_trajectory.empty());
	EXPECT_FALSE(std::filesystem::exists(out("trajectory_slam.tum")));
}

TEST_F(RunLoop, ModeLoRunsNoVisualOdometryAndModeVoNoLidarOdometry)
{
	const RunSummary lo = run({"pipeline.mode=lo"});
	EXPECT_EQ(seen.vo_frames, 0);
	EXPECT_EQ(seen.lidar_guesses.size(), std::size_t(kFrames));
	for (const auto& g : seen.lidar_guesses) EXPECT_FALSE(g);
	EXPECT_EQ(lo.final_trajectory, "trajectory_lo.tum");
	EXPECT_FALSE(std::filesystem::exists(out("trajectory_vo.tum")));
	EXPECT_EQ(header(out("frames.csv")), (std::vector<std::string>{"frame", "t", "x", "y", "z", "lo_point_times", "lo_fake", "ms_total"}));
	// summary.json carries the end-of-run timing table: one entry per ms_* column, here ms_total of every frame.
	std::ifstream summaryFile(out("summary.json"));
	const auto summary = nlohmann::json::parse(summaryFile);
	ASSERT_EQ(summary["stage_timings"].size(), 1u);
	const auto& total = summary["stage_timings"][0];
	EXPECT_EQ(total["stage"], "ms_total");
	EXPECT_EQ(total["frames"], kFrames);
	ASSERT_EQ(lo.stage_timings.size(), 1u);
	EXPECT_DOUBLE_EQ(total["mean_ms"].get<double>(), lo.stage_timings[0].mean);
	EXPECT_LE(total["mean_ms"].get<double>(), total["max_ms"].get<double>());
	EXPECT_LE(total["p95_ms"].get<double>(), total["max_ms"].get<double>());

	seen = {};
	std::filesystem::remove_all(out(""));
	const RunSummary vo = run({"pipeline.mode=vo"});
	EXPECT_EQ(seen.vo_frames, kFrames);
	EXPECT_TRUE(seen.lidar_guesses.empty());
	EXPECT_TRUE(seen.rescales.empty());  // the VO alone: no scale correction
	EXPECT_EQ(vo.final_trajectory, "trajectory_vo.tum");
	const Trajectory t = io::readTum(out("trajectory_vo.tum"));
	ASSERT_EQ(t.size(), std::size_t(kFrames - 1));  // not tracked at frame 0
	EXPECT_NEAR(t.back().pose.translation().x(), 5.0, 1e-6);  // the VO's own pose in vehicle axes, map units
}

// The motion source's trajectory is cut at the last row's time as the frame has it, not as frames.csv
// rounds it: t = 0.5000004 s is written 0.500000, which once dropped the VO's pose at that frame.
TEST_F(RunLoop, TheMotionSourceKeepsItsPoseAtTheLastFrameWhateverTheCsvRounding)
{
	test::writeSmallDrive(dir_ + "/drive.rawlog", kFrames, test::smallRig(), 4e-7);
	run({"pipeline.mode=vo"});
	const Trajectory t = io::readTum(out("trajectory_vo.tum"));
	ASSERT_EQ(t.size(), std::size_t(kFrames - 1));  // not tracked at frame 0
	EXPECT_EQ(column(out("frames.csv"), "t").back(), "0.500000");
	EXPECT_NEAR(t.back().t, 0.5000004, 1e-9);
}

TEST_F(RunLoop, AMetricVoNeedsNoScaleCorrection)
{
	run({"pipeline.mode=vlo", "pipeline.motion_source=visual", "pipeline.visual_odometry=fake_stereo"});
	ASSERT_EQ(seen.lidar_guesses.size(), std::size_t(kFrames));
	EXPECT_FALSE(seen.lidar_guesses[0]);
	for (int i = 1; i < kFrames; ++i)
	{
		ASSERT_TRUE(seen.lidar_guesses[i]);
		EXPECT_DOUBLE_EQ(seen.lidar_guesses[i]->motion.translation().x(), kStep);
		EXPECT_TRUE(std::isnan(seen.lidar_guesses[i]->quality.length_error));  // no scale estimate
	}
	EXPECT_TRUE(seen.scale_prev_index.empty());
}

TEST_F(RunLoop, BadModuleNamesAreInputErrors)
{
	EXPECT_NE(runError({"pipeline.lidar_odometry=nope"}).find("--set pipeline.lidar_odometry=nope: unknown module 'nope'"),
		std::string::npos);
	EXPECT_NE(runError({"pipeline.motion_source=nope"}).find("known: metric_mono, visual"), std::string::npos);
	EXPECT_NE(runError({"pipeline.scale_correction=nope"}).find("--set pipeline.scale_correction=nope: unknown module"),
		std::string::npos);  // in mode lo too, which runs no scale correction
	EXPECT_NE(runError({"pipeline.mode=vlo", "pipeline.visual_odometry=fake_stereo"}).find("'fake_stereo' is not a monocular VO"),
		std::string::npos);
	EXPECT_FALSE(std::filesystem::exists(out("frames.csv")));
}

TEST_F(RunLoop, OneAndTwoThreadsGiveTheSameOutputs)
{
	std::vector<std::string> csv;
	for (const char* threads : {"1", "2"})
	{
		seen = {};
		std::filesystem::remove_all(out(""));
		run({"pipeline.mode=vlo", std::string("pipeline.threads=") + threads});
		EXPECT_EQ(seen.scale_prev_index, (std::vector<long>{-1, 0, 1, 2, 3, 4})) << threads;
		ASSERT_EQ(seen.lidar_guesses.size(), std::size_t(kFrames));
		EXPECT_NEAR(seen.lidar_guesses[4]->motion.translation().x(), 0.55, 1e-12) << threads;
		std::string text;
		const auto names = header(out("frames.csv"));
		for (const auto& name : names)
			if (name.rfind("ms_", 0) != 0) text += name + ":" + [&] {
				std::string cells;
				for (const auto& c : column(out("frames.csv"), name)) cells += c + ",";
				return cells;
			}() +
				"\n";
		csv.push_back(text);
	}
	EXPECT_EQ(csv[0], csv[1]);
	EXPECT_NE(csv[0].find("vo_fake:0,1,2,3,4,5,"), std::string::npos) << csv[0];
}

TEST_F(RunLoop, AFailingModuleStopsTheRunWithItsErrorWhateverTheThreads)
{
	for (const char* threads : {"1", "2"})
	{
		const std::string t = std::string("pipeline.threads=") + threads;
		std::filesystem::remove_all(out(""));
		EXPECT_NE(runError({"pipeline.mode=vlo", t, "pipeline.lidar_odometry=failing_lidar"}).find("fails at frame 3"),
			std::string::npos)
			<< threads;
		EXPECT_NE(runError({"pipeline.mode=vlo", t, "pipeline.visual_odometry=failing_mono"}).find("fails at frame 4"),
			std::string::npos)
			<< threads;
		// Both: the LiDAR odometry of frame 3 fails first, as in a serial run, though with two threads the
		// motion source of frame 4 fails at the same time.
		EXPECT_NE(runError({"pipeline.mode=vlo", t, "pipeline.lidar_odometry=failing_lidar",
							   "pipeline.visual_odometry=failing_mono"})
					  .find("fails at frame 3"),
			std::string::npos)
			<< threads;
		EXPECT_NE(runError({"pipeline.mode=vlo", t, "pipeline.threads=3"}).find("threads"), std::string::npos);
		EXPECT_FALSE(std::filesystem::exists(out("frames.csv")));
	}
}

// Issue 34, section 2: Ctrl-C keeps the frames computed. The signal's flag stays set for the process, so
// each run is in a child process (a death test), which leaves its run folder for this one to check.
TEST_F(RunLoop, CtrlCKeepsAConsistentRunOfTheFramesComputed)
{
	for (const char* threads : {"1", "2"})
	{
		std::filesystem::remove_all(out(""));
		const std::vector<std::string> sets = {"pipeline.mode=vlo", std::string("pipeline.threads=") + threads,
			"pipeline.lidar_odometry=interrupted_lidar"};
		EXPECT_EXIT(
			{
				installInterruptHandler();
				try
				{
					run(sets);
				}
				catch (const Interrupted& e)
				{
					std::fprintf(stderr, "interrupted: %s\n", e.what());
					std::exit(130);
				}
				std::exit(0);
			},
			::testing::ExitedWithCode(130), "interrupted: the 4 frames up to frame 3 are kept in .*out")
			<< threads;
		std::ifstream in(out("summary.json"));
		ASSERT_TRUE(in) << threads;
		const auto summary = nlohmann::json::parse(in);
		EXPECT_EQ(summary["complete"], false);
		EXPECT_EQ(summary["stop_reason"], "interrupted (Ctrl-C or SIGTERM)");
		EXPECT_EQ(summary["last_frame"], 3);
		EXPECT_EQ(summary["frames"], 4);
		EXPECT_EQ(column(out("frames.csv"), "frame"), (std::vector<std::string>{"0", "1", "2", "3"})) << threads;
		// Every trajectory ends at the last row, also the motion source's, which with two threads ran ahead.
		for (const char* traj : {"trajectory_vlo.tum", "trajectory_vo.tum"})
		{
			const Trajectory t = io::readTum(out(traj));
			ASSERT_FALSE(t.empty()) << traj;
			EXPECT_NEAR(t.back().t, 0.3, 1e-9) << traj << " threads " << threads;
		}
		std::ifstream manifest(out(".vlo-run-files"));
		std::string files((std::istreambuf_iterator<char>(manifest)), {});
		for (const char* f : {"summary.json", "frames.csv", "run.ini", "report.md", "trajectory_vlo.tum"})
			EXPECT_NE(files.find(f), std::string::npos) << f << " not in the run's list of files";
	}
}

// Issue 34, section 1: with the rig's camera 0 known (here --kitti-calib), a trajectory with a pose for every
// frame is also written as KITTI poses; the VO's, which starts at frame 1, is not (the devkit pairs by line).
TEST_F(RunLoop, KittiPosesForTrajectoriesWithAPoseForEveryFrame)
{
	std::ofstream(dir_ + "/calib.txt") << "P0: 50 0 20 0 0 50 15 0 0 0 1 0\nTr: 0 -1 0 0 0 0 -1 0 1 0 0 0\n";
	std::ofstream(dir_ + "/run.ini") << "[pipeline]\nvisual_odometry = fake_mono\nscale_correction = fake_scale\n"
										"lidar_odometry = fake_lidar\nsnapshots = false\nmap_every = 0\n";
	RunRequest req{dir_ + "/drive.rawlog", dir_ + "/run.ini", dir_ + "/out", {"pipeline.mode=vlo"}, ""};
	req.kitti_calib = dir_ + "/calib.txt";
	runPipeline(req);
	const Trajectory kitti = io::readKittiPoses(out("trajectory_vlo.kitti.txt"));
	ASSERT_EQ(kitti.size(), std::size_t(kFrames));
	// The vehicle's 0.5 m per frame along its x is camera 0's z.
	EXPECT_NEAR(kitti.back().pose.translation().z(), kStep * (kFrames - 1), 1e-9);
	EXPECT_NEAR(kitti.back().pose.translation().norm(), kStep * (kFrames - 1), 1e-9);
	EXPECT_TRUE(std::filesystem::exists(out("trajectory_vo.tum")));
	EXPECT_FALSE(std::filesystem::exists(out("trajectory_vo.kitti.txt")));
}
