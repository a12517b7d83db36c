// Driven by tests/e2e/sim_kitti_roundtrip.sh: a vlo-sim rawlog and the vlo-import of its --kitti-dir
// export must hold the same frames. Skipped when run without the two files.
#include <gtest/gtest.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>

#include <cstdlib>
#include <cstring>

using namespace vlo;

TEST(KittiRoundTrip, ImportedExportHoldsTheSameFrames)
{
	const char* simPath = std::getenv("VLO_RT_SIM");
	const char* impPath = std::getenv("VLO_RT_IMPORTED");
	if (!simPath || !impPath) GTEST_SKIP() << "run by tests/e2e/sim_kitti_roundtrip.sh (VLO_RT_SIM, VLO_RT_IMPORTED)";
	RawlogReader sim(simPath), imp(impPath);
	Frame a, b;
	std::size_t n = 0;
	Eigen::Isometry3d L = Eigen::Isometry3d::Identity();  // vehicle_T_lidar of the simulator
	while (sim.next(a))
	{
		ASSERT_TRUE(imp.next(b)) << "imported rawlog ends at frame " << n;
		EXPECT_NEAR(a.t, b.t, 1e-6) << n;
		ASSERT_EQ(a.scan.size(), b.scan.size()) << n;
		for (std::size_t i = 0; i < a.scan.size(); ++i)
			ASSERT_TRUE(a.scan[i].x == b.scan[i].x && a.scan[i].y == b.scan[i].y && a.scan[i].z == b.scan[i].z &&
				a.scan[i].intensity == b.scan[i].intensity)
				<< "frame " << n << " point " << i;
		ASSERT_EQ(a.image.getWidth(), b.image.getWidth());
		for (unsigned r = 0; r < a.image.getHeight(); ++r)
			ASSERT_EQ(std::memcmp(a.image.ptrLine<uint8_t>(r), b.image.ptrLine<uint8_t>(r), a.image.getWidth()), 0) << n;
		// Imported: vehicle = Velodyne frame. The LiDAR-to-camera extrinsic must survive the trip.
		EXPECT_TRUE(b.rig.vehicle_T_lidar.isApprox(Eigen::Isometry3d::Identity(), 1e-9));
		EXPECT_TRUE(a.rig.camera_T_lidar().isApprox(b.rig.camera_T_lidar(), 1e-9));
		EXPECT_NEAR(a.rig.camera.fx, b.rig.camera.fx, 1e-6);
		EXPECT_NEAR(a.rig.camera.cx, b.rig.camera.cx, 1e-6);
		L = a.rig.vehicle_T_lidar;
		++n;
	}
	EXPECT_FALSE(imp.next(b)) << "imported rawlog has more frames";
	EXPECT_GT(n, 0u);
	// Ground truth: the importer's vehicle is the LiDAR, so its poses are the simulator's conjugated by L.
	const Trajectory gs = readTum(groundTruthPathFor(simPath)), gi = readTum(groundTruthPathFor(impPath));
	ASSERT_EQ(gs.size(), gi.size());
	for (std::size_t k = 0; k < gs.size(); ++k)
	{
		EXPECT_NEAR(gs[k].t, gi[k].t, 1e-6);
		EXPECT_TRUE((L.inverse() * gs[k].pose * L).isApprox(gi[k].pose, 1e-6)) << "pose " << k;
	}
}
