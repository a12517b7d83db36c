// Tracking on a short sequence of the project's simulator (vlo-sim, urban, VLP-16 rig camera):
// initialises, tracks to the end, Sim(3) ATE under a bound. tests/CMakeLists.txt builds vlo-sim before test_vo.
#include <gtest/gtest.h>
#include <vlo/io/rawlog_reader.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "vo_test_util.h"

using namespace vlo;
using namespace vlo::vo;

namespace fs = std::filesystem;

TEST(Simulator, UrbanSequenceWithinSim3Bound)
{
	const std::string sim = VLO_BIN_DIR "/vlo-sim";
	ASSERT_TRUE(fs::exists(sim)) << sim << " not built (build target vlo-sim)";
	const fs::path dir = fs::temp_directory_path() / ("vlo_test_vo_sim_" + std::to_string(::getpid()));
	fs::remove_all(dir);
	fs::create_directories(dir);
	const std::string rawlog = (dir / "urban.rawlog").string();
	const std::string cmd = sim + " --scenario urban --lidar vlp16 --frames 50 --seed 5 --quiet --out '" + rawlog + "'";
	ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

	io::RawlogReaderOptions ropt;
	ropt.need_lidar = false;
	io::RawlogReader reader(rawlog, ropt);
	Frame f;
	std::unique_ptr<VisualOdometry> vo;
	Trajectory est;
	int frames = 0, first = -1, reinits = 0;
	while (reader.next(f))
	{
		if (!vo) vo = std::make_unique<VisualOdometry>(f.rig.camera, VoOptions());
		const auto info = vo->process(f.image.asCvMatRef(), f.t);
		reinits = info.reinits;
		if (info.pose)
		{
			if (first < 0) first = frames;
			est.push_back({f.t, test::toVehicle(f.rig, *info.pose, info.metric)});
		}
		++frames;
	}
	ASSERT_EQ(frames, 50);
	ASSERT_GE(first, 0);
	EXPECT_LE(first, 5);
	EXPECT_EQ(static_cast<int>(est.size()), frames - first);
	EXPECT_EQ(reinits, 0);
	const Trajectory gt = io::readTum((dir / "urban.gt.tum").string());
	const auto ate = test::ateSim3(gt, est);
	const double length = pathLength(gt);
	std::cout << "vlo-sim urban (VLP-16 rig camera), 50 frames: Sim(3) ATE " << ate.ate_rmse_m << " m over " << length
			  << " m\n";
	EXPECT_LT(ate.ate_rmse_m, 0.01 * length);
	fs::remove_all(dir);
}
