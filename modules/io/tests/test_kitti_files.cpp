// KITTI calibration, Velodyne .bin and timestamp files.
#include "io_test_util.h"

#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>

#include <cmath>
#include <fstream>
#include <limits>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
const char* kOdometryCalib =
	"P0: 7.070912e+02 0 6.018873e+02 0 0 7.070912e+02 1.831104e+02 0 0 0 1 0\n"
	"P1: 7.070912e+02 0 6.018873e+02 -3.798145e+02 0 7.070912e+02 1.831104e+02 0 0 0 1 0\n"
	"Tr: -1.857739e-03 -9.999659e-01 -8.039975e-03 -4.784029e-03 -6.481465e-04 8.051860e-03 -9.999674e-01 "
	"-7.337429e-02 9.999981e-01 -1.805528e-03 -6.627484e-04 -3.339968e-01\n";
}  // namespace

TEST(KittiCalib, OdometryCalibWithAndWithoutTr)
{
	const std::string dir = freshDir();
	const auto c = readKittiOdometryCalib(writeFile(dir + "/calib.txt", kOdometryCalib));
	EXPECT_DOUBLE_EQ(c.P0(0, 0), 707.0912);
	EXPECT_DOUBLE_EQ(c.P0(1, 2), 183.1104);
	ASSERT_TRUE(c.has_tr);
	EXPECT_NEAR(c.cam0_T_velo.translation().z(), -0.3339968, 1e-12);
	EXPECT_NEAR((c.cam0_T_velo.rotation() * c.cam0_T_velo.rotation().transpose() - Eigen::Matrix3d::Identity()).norm(),
		0, 1e-12);
	EXPECT_NEAR(c.cam0_T_velo.rotation()(2, 0), 0.9999981, 1e-5);

	const auto n = readKittiOdometryCalib(writeFile(dir + "/notr.txt", "P0: 700 0 600 0 0 700 180 0 0 0 1 0\n"));
	EXPECT_FALSE(n.has_tr);
	// Nominal: vehicle x forward is camera z, vehicle y left is camera -x, vehicle z up is camera -y.
	EXPECT_TRUE((n.cam0_T_velo * Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(0, 0, 1)));
	EXPECT_TRUE((n.cam0_T_velo * Eigen::Vector3d(0, 1, 0)).isApprox(Eigen::Vector3d(-1, 0, 0)));
	EXPECT_TRUE((n.cam0_T_velo * Eigen::Vector3d(0, 0, 1)).isApprox(Eigen::Vector3d(0, -1, 0)));
}

TEST(KittiCalib, MissingOrMalformedKeyNamesFileAndKey)
{
	const std::string dir = freshDir();
	const auto readCalib = [](const std::string& path) { readKittiOdometryCalib(path); };
	expectRefused(dir + "/a.txt", "P1: 1 2 3 4 5 6 7 8 9 10 11 12\n", readCalib, {"missing key 'P0'"});
	expectRefused(dir + "/b.txt", "P0: 1 2 3\n", readCalib, {"key 'P0' has 3 numbers, expected 12"});
	expectRefused(dir + "/c.txt", "P0: 1 2 3 4 5 6 7 8 9 10 11 x\n", readCalib, {"key 'P0' does not hold numbers"});
	expectInputError([&] { readKittiOdometryCalib(dir + "/none.txt"); }, {dir + "/none.txt", "cannot open"});

	const std::string raw = sharedData("kitti_raw_2011_09_26_sample");
	std::ifstream in(raw + "/calib_cam_to_cam.txt");
	std::string line, without;
	while (std::getline(in, line))
		if (line.rfind("R_rect_00", 0) != 0) without += line + "\n";
	const std::string cc = writeFile(dir + "/calib_cam_to_cam.txt", without);
	expectInputError([&] { readKittiRawCalib(cc, raw + "/calib_velo_to_cam.txt", 2); }, {cc, "missing key 'R_rect_00'"});
	const std::string vc = writeFile(dir + "/calib_velo_to_cam.txt", "R: 1 0 0 0 1 0 0 0 1\n");
	expectInputError([&] { readKittiRawCalib(raw + "/calib_cam_to_cam.txt", vc, 2); }, {vc, "missing key 'T'"});
}

TEST(KittiCalib, RectifiedProjectionSplitsIntoIntrinsicsAndOffset)
{
	Matrix34d P;
	const Eigen::Vector3d t(0.06, -0.0004, 0.0027);
	Eigen::Matrix3d K;
	K << 721.5, 0, 609.6, 0, 721.5, 172.9, 0, 0, 1;
	P.leftCols<3>() = K;
	P.col(3) = K * t;
	EXPECT_TRUE(offsetOf(P).isApprox(t, 1e-12));
	const auto cam = intrinsicsOf(P, 1242, 375);
	EXPECT_EQ(cam.fx, 721.5);
	EXPECT_EQ(cam.cy, 172.9);
	EXPECT_EQ(cam.width, 1242);
}

TEST(KittiBin, RoundTripSizeCheckAndInvalidPoints)
{
	const std::string dir = freshDir();
	const PointCloud cloud = {{1, 2, 3, 0.5f}, {-4, 5.5f, -6, 0}, {7, 8, 9, 1}};
	writeKittiBin(dir + "/a.bin", cloud);
	PointCloud back;
	EXPECT_EQ(readKittiBin(dir + "/a.bin", back), 0u);
	ASSERT_EQ(back.size(), 3u);
	EXPECT_EQ(back[1].y, 5.5f);
	EXPECT_EQ(back[2].intensity, 1.0f);

	const float nan = std::numeric_limits<float>::quiet_NaN();
	writeKittiBin(dir + "/nan.bin", {{1, 2, 3, 0}, {nan, 0, 0, 0}, {0, 0, std::numeric_limits<float>::infinity(), 0}});
	EXPECT_EQ(readKittiBin(dir + "/nan.bin", back), 2u);
	EXPECT_EQ(back.size(), 1u);

	{
		std::ofstream f(dir + "/odd.bin", std::ios::binary);
		f << std::string(16 * 3 + 5, '\0');
	}
	expectInputError([&] { readKittiBin(dir + "/odd.bin", back); }, {dir + "/odd.bin", "53 bytes", "not a multiple of 16"});
	expectInputError([&] { readKittiBin(dir + "/none.bin", back); }, {dir + "/none.bin"});
}

TEST(KittiTimestamps, DatesBecomeUnixSeconds)
{
	double t = 0;
	ASSERT_TRUE(parseKittiDate("2011-09-26 13:02:25.964389445", t));
	EXPECT_NEAR(t, 1317042145.964389445, 1e-6);  // date -u -d '2011-09-26 13:02:25' +%s = 1317042145
	ASSERT_TRUE(parseKittiDate("2011-09-26 13:02:26\r", t));
	EXPECT_EQ(t, 1317042146.0);
	EXPECT_FALSE(parseKittiDate("2011-09-26", t));
	EXPECT_FALSE(parseKittiDate("2011-13-26 13:02:26", t));
	EXPECT_FALSE(parseKittiDate("2011-09-26 13:02:26.5 junk", t));

	const std::string dir = freshDir();
	const auto times = readKittiRawTimestamps(
		writeFile(dir + "/ok.txt", "2011-09-26 13:02:25.964389445\n2011-09-26 13:02:26.074578832\n"));
	ASSERT_EQ(times.size(), 2u);
	EXPECT_NEAR(times[1] - times[0], 0.110189387, 1e-6);
	const auto readDates = [](const std::string& path) { readKittiRawTimestamps(path); };
	expectRefused(dir + "/back.txt", "2011-09-26 13:02:26.0\n2011-09-26 13:02:25.9\n", readDates, {"line 2", "not after"});
	expectRefused(dir + "/bad.txt", "2011-09-26 13:02:26.0\nyesterday\n", readDates, {"line 2", "'yesterday' is not a date"});
}
