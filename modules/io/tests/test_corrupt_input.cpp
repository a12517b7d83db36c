// Inputs found by fuzzing (fuzz/, doc/ROBUSTNESS.md) that once crashed a reader or failed with the wrong
// error: each must now give one InputError line naming the file.
#include "io_test_util.h"

#include <vlo/io/frame_observations.h>
#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/lidar_observations.h>
#include <vlo/io/trajectory.h>

#include <mrpt/io/CMemoryStream.h>
#include <sys/resource.h>

#include <fstream>
#include <iterator>
#include <limits>
#include <regex>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
/// What `ulimit -v 4000000` does: MRPT would otherwise be free to allocate tens of GB.
void limitAddressSpace()
{
#if !defined(VLO_ADDRESS_SANITIZER)
	const rlimit limit{4000000000ul, 4000000000ul};
	setrlimit(RLIMIT_AS, &limit);
#endif
}

/// The real file `name` of the KITTI raw sample with the first match of `pattern` replaced.
std::string rawCalibWith(const std::string& name, const std::string& pattern, const std::string& replacement,
	const std::string& dir)
{
	std::ifstream in(sharedData("kitti_raw_2011_09_26_sample") + "/" + name);
	const std::string text((std::istreambuf_iterator<char>(in)), {});
	const std::string changed = std::regex_replace(text, std::regex(pattern), replacement, std::regex_constants::format_first_only);
	EXPECT_NE(changed, text) << pattern;
	return writeFile(dir + "/" + name, changed);
}

const char* kOdometryCalib =
	"P0: 7.070912e+02 0 6.018873e+02 0 0 7.070912e+02 1.831104e+02 0 0 0 1 0\n"
	"Tr: -1.857739e-03 -9.999659e-01 -8.039975e-03 -4.784029e-03 -6.481465e-04 8.051860e-03 -9.999674e-01 "
	"-7.337429e-02 9.999981e-01 -1.805528e-03 -6.627484e-04 -3.339968e-01\n";
}  // namespace

// 8 bytes near an object header overwritten: MRPT's CPointsMapXYZI::serializeFrom resized its arrays to
// the corrupt count through an allocator that returned null, and the process segfaulted. (Which error
// comes first, the sensor pose or the count, is the reader's choice: one line naming the file.)
TEST(CorruptInput, RawlogWithAHugePointCountIsAOneLineError)
{
	limitAddressSpace();
	const std::string dir = sharedData("corrupt_rawlogs");
	for (const std::string name : {"pointcloud_count_33", "pointcloud_count_45"})
	{
		const std::string path = dir + "/" + name + ".rawlog";
		expectInputError([&] { readFrames(path); }, {path});
	}
}

// A rawlog whose camera or LiDAR pose holds NaN was read, and every point or pixel bent by it.
TEST(CorruptInput, RawlogSensorPoseThatIsNoRigidTransformIsAnError)
{
	const std::string dir = freshDir();
	const double nan = std::numeric_limits<double>::quiet_NaN();
	for (const bool camera : {true, false})
	{
		const std::string path = dir + (camera ? "/camera.rawlog" : "/lidar.rawlog");
		{
			RawlogWriter w(path, false);
			auto image = toImageObservation(testFrame(0, 0.0), "CAMERA");
			auto scan = toScanObservation(testFrame(0, 0.0), "LIDAR");
			if (camera)
				image->cameraPose.setFromValues(1, 2, 3, nan, 0, 0);
			else
				scan->setSensorPose(mrpt::poses::CPose3D(1, 2, 3, 0, nan, 0));
			w.write(*image);
			w.write(*scan);
			w.commit();
		}
		expectInputError([&] { readFrames(path); }, {path, camera ? "'CAMERA'" : "'LIDAR'", "sensor pose is not a rigid transform"});
	}
}

// 1e308 in a projection made its offset K^-1 t infinite, silently; a zero rotation became the identity.
TEST(CorruptInput, KittiCalibrationThatIsNoProjectionOrRotationIsAnError)
{
	const std::string dir = freshDir();
	std::string calib = kOdometryCalib;
	const auto readCalib = [](const std::string& path) { readKittiOdometryCalib(path); };
	expectRefused(dir + "/p.txt", std::regex_replace(calib, std::regex("6.018873e\\+02"), "1e308"), readCalib,
		{"P0 is not a rectified projection"});
	expectRefused(dir + "/tr.txt", std::regex_replace(calib, std::regex("Tr: .*"), "Tr: 0 0 0 1 0 0 0 2 0 0 0 3"), readCalib,
		{"Tr is not a rigid transform"});
	EXPECT_NO_THROW(readKittiOdometryCalib(writeFile(dir + "/good.txt", calib)));

	const std::string raw = sharedData("kitti_raw_2011_09_26_sample");
	const std::string velo = raw + "/calib_velo_to_cam.txt", cam = raw + "/calib_cam_to_cam.txt";
	const std::string size = rawCalibWith("calib_cam_to_cam.txt", "S_rect_02: [^ ]+", "S_rect_02: 1e308", dir);
	expectInputError([&] { readKittiRawCalib(size, velo, 2); }, {size, "S_rect_02 is not an image size"});
	const std::string proj = rawCalibWith("calib_cam_to_cam.txt", "(P_rect_02: [^ ]+ [^ ]+ [^ ]+ [^ ]+ [^ ]+ [^ ]+ [^ ]+ [^ ]+ [^ ]+) [^ ]+",
		"$1 1e308", dir);
	expectInputError([&] { readKittiRawCalib(proj, velo, 2); }, {proj, "P_rect_02 is not a rectified projection"});
	const std::string rot = rawCalibWith("calib_velo_to_cam.txt", "R: .*", "R: 0 0 0 0 0 0 0 0 0", dir);
	expectInputError([&] { readKittiRawCalib(cam, rot, 2); }, {rot, "R, T is not a rigid transform"});
}

// A control byte in a malformed token went verbatim into the message (not one printable line).
TEST(CorruptInput, MalformedTextIsQuotedPrintably)
{
	const std::string dir = freshDir();
	expectRefused(dir + "/times.txt", "0.0\n1.0\x10x\n", [](const std::string& p) { readKittiTimes(p); },
		{"line 2: '1.0?x' is not a number"});
	expectRefused(dir + "/t.tum", "0 0 0 0 0 0 0 1\x1b\n", [](const std::string& p) { readTum(p); },
		{"line 1: '1?' is not a number"});
	expectRefused(dir + "/timestamps.txt", "2011-09-26 13:02:25.0\x07\n", [](const std::string& p) { readKittiRawTimestamps(p); },
		{"'2011-09-26 13:02:25.0?' is not a date"});
}

// MRPT decodes inline JPEG images (CImage::serializeFrom, a bit flipped in a rawlog) with libjpeg's
// default error handler, which ended the process: exit 1, "Not a JPEG file: starts with 0x00 0x00".
// vlo::corrupt_input_guard, which this test links as the apps do, makes it throw; the reader's catch turns
// the exception into its one-line "corrupt rawlog" error.
TEST(CorruptInput, CorruptJpegDataThrowsInsteadOfEndingTheProcess)
{
	const std::string garbage(256, '\0');
	mrpt::io::CMemoryStream stream(garbage.data(), garbage.size());
	mrpt::img::CImage image;
	try
	{
		image.loadFromStreamAsJPEG(stream);
		ADD_FAILURE() << "no exception";
	}
	catch (const std::exception& e)  // MRPT wraps it in its own exception
	{
		EXPECT_NE(std::string(e.what()).find("JPEG image: Not a JPEG file"), std::string::npos) << e.what();
	}
}
