// A vlo-sim rawlog and the vlo-import of its --kitti-dir export must hold the same frames (times, points, images,
// extrinsic) and the same ground truth. Runs both apps (tests/CMakeLists.txt builds them before test_sim).
#include <gtest/gtest.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <unistd.h>

using namespace vlo;

namespace fs = std::filesystem;

TEST(KittiRoundTrip, ImportedExportHoldsTheSameFrames)
{
	const fs::path dir = fs::temp_directory_path() / ("vlo_test_sim_roundtrip_" + std::to_string(::getpid()));
	fs::remove_all(dir);
	fs::create_directories(dir);
	const std::string bin = VLO_BIN_DIR, simRawlog = (dir / "sim.rawlog").string(),
					  imported = (dir / "imported.rawlog").string(), kitti = (dir / "kitti").string();
	const std::string simCmd = bin + "/vlo-sim --scenario urban --lidar vlp16 --frames 5 --seed 4 --no-realism --lidar-distortion" +
		" --quiet --out '" + simRawlog + "' --kitti-dir '" + kitti + "'";
	ASSERT_EQ(std::system(simCmd.c_str()), 0) << simCmd;
	const std::string importCmd = bin + "/vlo-import kitti-odometry --root '" + kitti + "' --seq 00 --out '" +
		imported + "' > '" + (dir / "import.log").string() + "'";
	ASSERT_EQ(std::system(importCmd.c_str()), 0) << importCmd;
	const char* simPath = simRawlog.c_str();
	const char* impPath = imported.c_str();
	io::RawlogReader sim(simPath), imp(impPath);
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
	EXPECT_EQ(n, 5u);  // --frames 5
	// Ground truth: the importer's vehicle is the LiDAR, so its poses are the simulator's conjugated by L.
	const Trajectory gs = io::readTum(io::groundTruthPathFor(simPath)), gi = io::readTum(io::groundTruthPathFor(impPath));
	ASSERT_EQ(gs.size(), gi.size());
	for (std::size_t k = 0; k < gs.size(); ++k)
	{
		EXPECT_NEAR(gs[k].t, gi[k].t, 1e-6);
		EXPECT_TRUE((L.inverse() * gs[k].pose * L).isApprox(gi[k].pose, 1e-6)) << "pose " << k;
	}
	fs::remove_all(dir);
}
