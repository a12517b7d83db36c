// The real KITTI 06 sample (51 frames): initialises, tracks every frame after it, Sim(3) ATE bound.
#include <gtest/gtest.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/rawlog_reader.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "vo_test_util.h"

using namespace vlo;
using namespace vlo::vo;

namespace fs = std::filesystem;

TEST(Kitti, Sequence06SampleWithinSim3Bound)
{
	const std::string archive = VLO_SHARED_DATA "/kitti_odometry_06_0000-0050.tar.xz";
	if (!fs::exists(archive))
		GTEST_SKIP() << "real-data test not run: " << archive << " not found (CI has ../shared/data beside the checkout)";
	const fs::path dir = fs::temp_directory_path() / ("vlo_test_vo_kitti06_" + std::to_string(::getpid()));
	fs::remove_all(dir);
	fs::create_directories(dir);
	ASSERT_EQ(std::system(("tar -xJf '" + archive + "' -C '" + dir.string() + "'").c_str()), 0);
	io::KittiOdometryImport imp;
	imp.root = (dir / "kitti_odometry_06_0000-0050").string();
	imp.seq = "06";
	imp.out = (dir / "06.rawlog").string();
	const auto summary = io::importKittiOdometry(imp);
	ASSERT_EQ(summary.frames, 51u);

	io::RawlogReaderOptions ropt;
	ropt.need_lidar = false;
	io::RawlogReader reader(imp.out, ropt);
	Frame f;
	std::unique_ptr<VisualOdometry> vo;
	Trajectory est;
	std::vector<VoFrameInfo> infos;
	while (reader.next(f))
	{
		if (!vo) vo = std::make_unique<VisualOdometry>(f.rig.camera, VoOptions());
		const auto info = vo->process(f.image.asCvMatRef(), f.t);
		infos.push_back(info);
		// Camera poses to vehicle poses, as the pipeline does.
		if (info.pose) est.push_back({f.t, test::toVehicle(f.rig, *info.pose, info.metric)});
	}
	ASSERT_EQ(infos.size(), 51u);
	const Trajectory gt = io::readTum(summary.ground_truth);
	int first = -1;
	for (const auto& i : infos)
		if (i.pose && first < 0) first = static_cast<int>(i.index);
	ASSERT_GE(first, 0) << infos[1].reason;
	EXPECT_LE(first, 10) << infos[1].reason;
	EXPECT_EQ(static_cast<int>(est.size()), 51 - first) << "lost frames";
	EXPECT_EQ(infos.back().reinits, 0);
	const auto ate = test::ateSim3(gt, est);
	const double length = pathLength(gt);
	RecordProperty("ate_m", std::to_string(ate.ate_rmse_m));
	std::cout << "KITTI 06 sample: first tracked frame " << first << ", Sim(3) ATE " << ate.ate_rmse_m << " m over "
			  << length << " m (" << 100 * ate.ate_rmse_m / length << " %)\n";
	EXPECT_LT(ate.ate_rmse_m, 0.02 * length);
	fs::remove_all(dir);
}
