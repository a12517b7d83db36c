// Real HDL-64E data: the KITTI raw sample (32 frames, slow traffic under a bridge, no ground truth)
// runs to the end without failing or jumping. Skipped when the shared data is absent.
#include <gtest/gtest.h>
#include <vlo/loam/lidar_odometry.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "kitti_data.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
namespace fs = std::filesystem;

// The scans, unpacked once into the build tree (xz takes a few seconds).
fs::path kittiScans()
{
	return sharedData("kitti_raw_2011_09_26_sample.tar.xz", "kitti_raw_2011_09_26_sample", "'*velodyne_points*'",
			   "velodyne_points/data/0000000031.bin") /
		"velodyne_points" / "data";
}
}  // namespace

TEST(KittiRaw, RunsToTheEndWithoutJumps)
{
	const fs::path scans = kittiScans();
	if (!fs::exists(scans / "0000000000.bin"))
		GTEST_SKIP() << "real-data test not run: no kitti_raw_2011_09_26_sample.tar.xz in " VLO_SHARED_DATA
					 << " (CI has ../shared/data beside the checkout)";
	LidarOdometry lo(hdl64Options());
	Eigen::Isometry3d prev = Eigen::Isometry3d::Identity();
	double length = 0, max_step = 0;
	for (int i = 0; i < 32; ++i)
	{
		char name[32];
		std::snprintf(name, sizeof name, "%010d.bin", i);
		const PointCloud pc = readKittiBin(scans / name);
		ASSERT_GT(pc.size(), 100000u);
		const LidarOdometryResult r = lo.process(0.1 * i, pc, std::nullopt);
		EXPECT_EQ(r.status, i == 0 ? LidarFrameStatus::Initialized : LidarFrameStatus::Ok) << i << ": " << r.reason;
		// Under the bridge the translation is weakly fixed (smallest eigenvalue 6-15 against the
		// degeneracy threshold's 10) but nothing like a corridor's (0.2).
		EXPECT_TRUE(i == 0 || r.mapping.degeneracy.min_eigenvalue > 3.0) << i << ": " << r.mapping.degeneracy.min_eigenvalue;
		const double step = (r.pose.translation() - prev.translation()).norm();
		length += step;
		max_step = std::max(max_step, step);
		prev = r.pose;
	}
	std::printf("KITTI raw sample: %.2f m driven, largest step %.3f m, final yaw %.2f deg\n", length, max_step,
		std::atan2(prev.linear()(1, 0), prev.linear()(0, 0)) * 180 / M_PI);
	// Slow stop-and-go traffic: about 6 m (the data's README; the icp module 6.2 m). Lines strewn over
	// surfaces pulled A-LOAM to 4.0 m (edge_flatness_ratio = 0).
	EXPECT_GT(length, 4.4);
	EXPECT_LT(length, 8.0);
	EXPECT_LT(max_step, 0.5);  // 5 m/s at most
	EXPECT_LT(std::abs(prev.translation().z()), 0.3);
}
}  // namespace vlo::loam::test
