// Bad rawlogs: each gives one clear InputError naming the file, never a crash.
#include "io_test_util.h"

#include <vlo/io/frame_observations.h>
#include <vlo/io/lidar_observations.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/rawlog_writer.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
std::string writeFrames(const std::string& path, std::size_t n, bool external = false, std::size_t points = 10)
{
	RawlogWriter w(path, external);
	for (std::size_t k = 0; k < n; ++k)
	{
		Frame f = testFrame(k, 0.1 * k);
		for (std::size_t p = f.scan.size(); p < points; ++p) f.scan.push_back({float(p), float(k), 1.0f, 0.5f});
		w.writeFrame(f);
	}
	w.commit();
	return path;
}

std::string fileBytes(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	return std::string(std::istreambuf_iterator<char>(in), {});
}

void putBytes(const std::string& path, const std::string& bytes)
{
	std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}
}  // namespace

TEST(RawlogErrors, MissingFile)
{
	const std::string path = freshDir() + "/none.rawlog";
	expectInputError([&] { RawlogReader r(path); }, {path, "not found"});
}

TEST(RawlogErrors, NotARawlog)
{
	const std::string dir = freshDir();
	putBytes(dir + "/text.rawlog", "P0: 1 2 3\nthis is no rawlog\n");
	expectInputError([&] { RawlogReader r(dir + "/text.rawlog"); }, {dir + "/text.rawlog", "not an MRPT rawlog"});
	putBytes(dir + "/empty.rawlog", "");
	expectInputError([&] { RawlogReader r(dir + "/empty.rawlog"); }, {"empty rawlog"});
	expectInputError([&] { RawlogReader r(dir); }, {dir, "is a directory, expected a file"});
}

TEST(RawlogErrors, TruncatedGzipAnywhereIsACleanError)
{
	const std::string dir = freshDir();
	const std::string bytes = fileBytes(writeFrames(dir + "/full.rawlog", 6, false, 3000));
	ASSERT_GT(bytes.size(), 1000u);
	const std::string cut = dir + "/cut.rawlog";
	for (double frac : {0.002, 0.01, 0.1, 0.37, 0.5, 0.9, 0.999})
	{
		putBytes(cut, bytes.substr(0, static_cast<std::size_t>(frac * bytes.size())));
		expectInputError([&] { readFrames(cut); }, {cut, "truncated"});
	}
	putBytes(cut, bytes.substr(0, bytes.size() - 1));  // only the gzip trailer is cut
	expectInputError([&] { readFrames(cut); }, {cut, "truncated"});
}

TEST(RawlogErrors, TruncatedOrCorruptUncompressedRawlog)
{
	const std::string dir = freshDir();
	writeFrames(dir + "/full.rawlog", 4, false, 500);
	const std::string plain = dir + "/plain.rawlog";
	ASSERT_EQ(std::system(("gzip -dc '" + dir + "/full.rawlog' > '" + plain + "'").c_str()), 0);
	EXPECT_EQ(readFrames(plain).size(), 4u);  // uncompressed rawlogs are read too
	const std::string bytes = fileBytes(plain), bad = dir + "/bad.rawlog";
	for (double frac : {0.05, 0.3, 0.6, 0.95})
	{
		putBytes(bad, bytes.substr(0, static_cast<std::size_t>(frac * bytes.size())));
		expectInputError([&] { readFrames(bad); }, {bad, "truncated: the file ends inside object"});
	}
	// Damage inside pixel or point payloads cannot be detected (no checksums); damage to the
	// structure can: here the class name of the fourth object.
	std::string damaged = bytes;
	const auto second = damaged.find("CObservationPointCloud", damaged.find("CObservationPointCloud") + 1);
	ASSERT_NE(second, std::string::npos);
	damaged[second + 5] = 'X';
	putBytes(bad, damaged);
	expectInputError([&] { readFrames(bad); }, {bad, "corrupt rawlog at object 4", "not registered"});
}

TEST(RawlogErrors, CorruptGzipData)
{
	const std::string dir = freshDir();
	std::string bytes = fileBytes(writeFrames(dir + "/full.rawlog", 6, false, 3000));
	for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 200; ++i) bytes[i] = static_cast<char>(i * 7);
	putBytes(dir + "/bad.rawlog", bytes);
	expectInputError([&] { readFrames(dir + "/bad.rawlog"); }, {dir + "/bad.rawlog"});
}

// Issue 34, defect 4: a corrupt string length (here the sensor label's, 6 -> 1 MB) made MRPT read past the end of
// a complete gzip file, which was reported as "truncated".
TEST(RawlogErrors, ACorruptLengthInACompleteGzipFileIsCorruptNotTruncated)
{
	const std::string dir = freshDir();
	writeFrames(dir + "/full.rawlog", 4, false, 500);
	const std::string plain = dir + "/plain.rawlog";
	ASSERT_EQ(std::system(("gzip -dc '" + dir + "/full.rawlog' > '" + plain + "'").c_str()), 0);
	std::string bytes = fileBytes(plain);
	const auto label = bytes.rfind(std::string("\x06\0\0\0CAMERA", 10));
	ASSERT_NE(label, std::string::npos);
	bytes[label + 2] = '\x10';  // 6 + 1 MB
	putBytes(plain, bytes);
	ASSERT_EQ(std::system(("gzip -c '" + plain + "' > '" + dir + "/bad.rawlog'").c_str()), 0);
	expectInputError([&] { readFrames(dir + "/bad.rawlog"); }, {dir + "/bad.rawlog: corrupt rawlog at object", "runs past the end"});
	expectInputError([&] { readFrames(plain); }, {plain, "truncated"});  // a plain file cannot tell the two apart
}

// Issue 34, defect 4: one flipped byte in a gzip rawlog said "empty rawlog: no observations" (zlib stops at
// the damage, which read as the end of the data).
TEST(RawlogErrors, OneFlippedByteOfAGzipRawlogIsCorruptNotEmpty)
{
	const std::string dir = freshDir();
	const std::string bytes = fileBytes(writeFrames(dir + "/full.rawlog", 6, false, 3000));
	const std::string bad = dir + "/flipped.rawlog";
	for (const std::size_t at : {std::size_t(10), std::size_t(11), std::size_t(16), std::size_t(64), bytes.size() / 2,
			 bytes.size() - 6})
	{
		std::string flipped = bytes;
		flipped[at] = static_cast<char>(flipped[at] ^ 0xFF);
		putBytes(bad, flipped);
		try
		{
			readFrames(bad);
			ADD_FAILURE() << "byte " << at << ": no error";
		}
		catch (const InputError& e)
		{
			const std::string m = e.what();
			EXPECT_NE(m.find(bad + ": corrupt"), std::string::npos) << "byte " << at << ": " << m;
			EXPECT_EQ(m.find("empty"), std::string::npos) << "byte " << at << ": " << m;
		}
	}
}

TEST(RawlogErrors, UnknownSensorLabelListsTheLabelsSeen)
{
	const std::string path = writeFrames(freshDir() + "/x.rawlog", 3);
	RawlogReaderOptions opt;
	opt.camera_label = "CAM0";
	expectInputError([&] { readFrames(path, opt); },
		{path, "no observations labelled 'CAM0'", "labels seen: 'CAMERA' x3, 'LIDAR' x3"});
}

TEST(RawlogErrors, TimestampsOutOfOrder)
{
	const std::string path = freshDir() + "/x.rawlog";
	{
		RawlogWriter w(path, false);
		for (double t : {0.0, 0.2, 0.1}) w.writeFrame(testFrame(0, t));
		w.commit();
	}
	expectInputError([&] { readFrames(path); }, {path, "out of order", "'CAMERA'", "t=0.100000 s", "t=0.200000 s"});
}

TEST(RawlogErrors, ImageSizeDiffersFromCameraParamsOrFirstImage)
{
	const std::string dir = freshDir();
	{
		RawlogWriter w(dir + "/params.rawlog", false);
		Frame f = testFrame(0, 0.0);
		f.rig.camera.width = 640;
		w.writeFrame(f);
		w.commit();
	}
	expectInputError([&] { readFrames(dir + "/params.rawlog"); }, {"is 64x48 but its cameraParams say 640x48"});
	{
		RawlogWriter w(dir + "/first.rawlog", false);
		w.writeFrame(testFrame(0, 0.0));
		w.writeFrame(testFrame(1, 0.1, 32, 48));
		w.commit();
	}
	expectInputError([&] { readFrames(dir + "/first.rawlog"); }, {"is 32x48 but the first image was 64x48"});
}

TEST(RawlogErrors, MissingExternalImage)
{
	const std::string dir = freshDir();
	writeFrames(dir + "/x.rawlog", 3, true);
	fs::remove(dir + "/x_Images/CAMERA_000001.png");
	expectInputError([&] { readFrames(dir + "/x.rawlog"); }, {dir + "/x_Images/CAMERA_000001.png", "cannot read image"});
}

TEST(RawlogErrors, WrongObservationClassOrBadDistortion)
{
	const std::string dir = freshDir();
	{
		RawlogWriter w(dir + "/class.rawlog", false);
		w.write(*toImageObservation(testFrame(0, 0.0), "LIDAR"));
		w.commit();
	}
	expectInputError([&] { readFrames(dir + "/class.rawlog"); }, {"'LIDAR' observation is a mrpt::obs::CObservationImage"});
	{
		RawlogWriter w(dir + "/dist.rawlog", false);
		auto obs = toImageObservation(testFrame(0, 0.0), "CAMERA");
		obs->cameraParams.distortion = mrpt::img::DistortionModel::plumb_bob;
		obs->cameraParams.dist[0] = std::numeric_limits<double>::quiet_NaN();
		w.write(*obs);
		w.write(*toScanObservation(testFrame(0, 0.0), "LIDAR"));
		w.commit();
	}
	expectInputError([&] { readFrames(dir + "/dist.rawlog"); }, {dir + "/dist.rawlog", "distortion coefficient"});
}
