// Writer -> reader round trips: frames, times (t = 0 included), rig, images, points, formats.
#include "io_test_util.h"

#include <vlo/io/frame_observations.h>
#include <vlo/io/lidar_observations.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/rawlog_writer.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <fstream>
#include <limits>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
void expectSameImage(const mrpt::img::CImage& a, const mrpt::img::CImage& b)
{
	ASSERT_EQ(a.getWidth(), b.getWidth());
	ASSERT_EQ(a.getHeight(), b.getHeight());
	ASSERT_FALSE(b.isColor());
	for (unsigned r = 0; r < a.getHeight(); ++r)
		for (unsigned c = 0; c < a.getWidth(); ++c) ASSERT_EQ(*a.ptr<uint8_t>(c, r), *b.ptr<uint8_t>(c, r));
}

class RoundTrip : public ::testing::TestWithParam<bool>
{
};
}  // namespace

TEST_P(RoundTrip, FramesTimesRigImagesAndPoints)
{
	const bool external = GetParam();
	const std::string dir = freshDir(external ? "_ext" : "_inline"), path = dir + "/x.rawlog";
	const std::vector<double> times = {0.0, 0.1044989, 0.2077935, 1317042145.964389};
	std::vector<Frame> in;
	{
		RawlogWriter w(path, external);
		for (std::size_t k = 0; k < times.size(); ++k)
		{
			in.push_back(testFrame(k, times[k]));
			if (k == 1)  // two invalid points must be dropped and counted
			{
				auto scan = in.back().scan;
				in.back().scan.push_back({std::numeric_limits<float>::quiet_NaN(), 1, 2, 0});
				in.back().scan.push_back({1, std::numeric_limits<float>::infinity(), 2, 0});
				w.writeFrame(in.back());
				in.back().scan = scan;
			}
			else
				w.writeFrame(in.back());
		}
		w.commit();
	}
	EXPECT_EQ(fs::is_directory(dir + "/x_Images"), external);
	EXPECT_FALSE(fs::exists(path + ".partial"));

	RawlogStats stats;
	const auto out = readFrames(path, {}, &stats);
	ASSERT_EQ(out.size(), in.size());
	EXPECT_EQ(stats.invalid_points, 2u);
	EXPECT_EQ(stats.unpaired_images + stats.unpaired_scans, 0u);
	for (std::size_t k = 0; k < in.size(); ++k)
	{
		EXPECT_EQ(out[k].index, k);
		EXPECT_NEAR(out[k].t, in[k].t, std::max(1e-7, std::abs(in[k].t) * 1e-15));  // 100 ns ticks; double ulp
		ASSERT_TRUE(out[k].has_image && out[k].has_scan);
		expectSameImage(in[k].image, out[k].image);
		ASSERT_EQ(out[k].scan.size(), in[k].scan.size());
		for (std::size_t p = 0; p < in[k].scan.size(); ++p)
		{
			EXPECT_EQ(out[k].scan[p].x, in[k].scan[p].x);
			EXPECT_EQ(out[k].scan[p].y, in[k].scan[p].y);
			EXPECT_EQ(out[k].scan[p].z, in[k].scan[p].z);
			EXPECT_EQ(out[k].scan[p].intensity, in[k].scan[p].intensity);
		}
		const auto& a = in[k].rig;
		const auto& b = out[k].rig;
		EXPECT_TRUE(b.has_camera && b.has_lidar);
		EXPECT_DOUBLE_EQ(b.camera.fx, a.camera.fx);
		EXPECT_DOUBLE_EQ(b.camera.fy, a.camera.fy);
		EXPECT_DOUBLE_EQ(b.camera.cx, a.camera.cx);
		EXPECT_DOUBLE_EQ(b.camera.cy, a.camera.cy);
		EXPECT_EQ(b.camera.width, a.camera.width);
		EXPECT_EQ(b.camera.height, a.camera.height);
		EXPECT_TRUE(b.vehicle_T_camera.isApprox(a.vehicle_T_camera, 1e-12));
		EXPECT_TRUE(b.vehicle_T_lidar.isApprox(a.vehicle_T_lidar, 1e-12));
	}
	EXPECT_EQ(out[0].t, 0.0);  // KITTI's first time is a valid time, not "no timestamp"
}
INSTANTIATE_TEST_SUITE_P(Images, RoundTrip, ::testing::Values(true, false));

TEST(RawlogWriter, PgmImagesReadBackIdentical)
{
	const std::string dir = freshDir("_pgm"), path = dir + "/x.rawlog";
	std::vector<Frame> in;
	{
		RawlogWriter w(path, true, RawlogCompression::None, ImageFileFormat::Pnm);
		for (std::size_t k = 0; k < 3; ++k)
		{
			in.push_back(testFrame(k, 0.1 * static_cast<double>(k)));
			w.writeFrame(in.back());
		}
		w.commit();
	}
	EXPECT_TRUE(fs::exists(dir + "/x_Images/CAMERA_000002.pgm"));
	EXPECT_FALSE(fs::exists(dir + "/x_Images/CAMERA_000002.png"));
	const auto out = readFrames(path);
	ASSERT_EQ(out.size(), in.size());
	for (std::size_t k = 0; k < in.size(); ++k)
	{
		ASSERT_TRUE(out[k].has_image);
		expectSameImage(in[k].image, out[k].image);
	}
	EXPECT_THROW(parseImageFileFormat("jpg", "--image-format"), InputError);
}

TEST(RawlogReader, ColourImagesBecomeGray)
{
	const std::string path = freshDir() + "/c.rawlog";
	{
		RawlogWriter w(path, false);
		Frame f = testFrame(0, 1.0);
		f.image = f.image.colorImage();
		ASSERT_TRUE(f.image.isColor());
		w.writeFrame(f);
		w.commit();
	}
	const auto out = readFrames(path);
	ASSERT_EQ(out.size(), 1u);
	expectSameImage(testFrame(0, 1.0).image, out[0].image);
}

TEST(RawlogReader, ReadsActionSensoryFrameFormat)
{
	const std::string path = freshDir() + "/sf.rawlog";
	{
		mrpt::io::CFileGZOutputStream f(path);
		auto ar = mrpt::serialization::archiveFrom(f);
		for (std::size_t k = 0; k < 3; ++k)
		{
			const Frame fr = testFrame(k, 10.0 + 0.1 * k);
			mrpt::obs::CActionCollection acts;
			mrpt::obs::CSensoryFrame sf;
			sf.insert(toImageObservation(fr, "CAMERA"));
			sf.insert(toScanObservation(fr, "LIDAR"));
			ar << acts << sf;
		}
	}
	const auto frames = readFrames(path);
	ASSERT_EQ(frames.size(), 3u);
	EXPECT_NEAR(frames[2].t, 10.2, 1e-6);
	EXPECT_EQ(frames[2].scan.size(), 10u);
	expectSameImage(testFrame(2, 0).image, frames[2].image);
}

TEST(RawlogReader, SingleSensorRunsAndOtherLabels)
{
	const std::string dir = freshDir();
	writeStreams(dir + "/cam.rawlog", {0.0, 0.1, 0.2}, {});
	RawlogReaderOptions camera_only;
	camera_only.need_lidar = false;
	const auto frames = readFrames(dir + "/cam.rawlog", camera_only);
	ASSERT_EQ(frames.size(), 3u);
	EXPECT_TRUE(frames[0].has_image);
	EXPECT_FALSE(frames[0].has_scan);

	// A LiDAR-only run keeps scans even when images with another label are present.
	{
		RawlogWriter w(dir + "/mixed.rawlog", false);
		for (std::size_t k = 0; k < 30; ++k) w.writeFrame(testFrame(k, 0.1 * k), "CAM_LEFT", "LIDAR");
		w.commit();
	}
	RawlogReaderOptions lidar_only;
	lidar_only.need_camera = false;
	RawlogStats stats;
	const auto scans = readFrames(dir + "/mixed.rawlog", lidar_only, &stats);
	ASSERT_EQ(scans.size(), 30u);
	EXPECT_FALSE(scans[29].has_image);
	EXPECT_TRUE(scans[29].has_scan);
	EXPECT_NEAR(scans[29].t, 2.9, 1e-6);
	EXPECT_EQ(stats.other_labels, 30u);
	EXPECT_EQ(stats.labels.at("CAM_LEFT"), 30u);
}

TEST(RawlogWriter, LeavesNothingWhenNotCommitted)
{
	const std::string dir = freshDir();
	{
		RawlogWriter w(dir + "/a.rawlog");
		w.writeFrame(testFrame(0, 0.0));
		EXPECT_TRUE(fs::exists(dir + "/a.rawlog.partial"));
	}  // e.g. an exception unwinds here
	EXPECT_TRUE(fs::is_empty(dir)) << "left behind: " << fs::directory_iterator(dir)->path();
}

TEST(RawlogWriter, CreatesTheOutputFolderAndReplacesOldImages)
{
	const std::string dir = freshDir(), path = dir + "/sub/a.rawlog";
	fs::create_directories(dir + "/sub/a_Images");
	std::ofstream(dir + "/sub/a_Images/stale.png") << "x";
	RawlogWriter w(path);
	w.writeFrame(testFrame(7, 0.0));
	w.commit();
	EXPECT_TRUE(fs::exists(path));
	EXPECT_TRUE(fs::exists(dir + "/sub/a_Images/CAMERA_000007.png"));
	EXPECT_FALSE(fs::exists(dir + "/sub/a_Images/stale.png"));
	EXPECT_EQ(w.observationsWritten(), 2u);
}

TEST(RawlogWriter, PlainRawlogReadsAsTheGzipOne)
{
	const std::string dir = freshDir("_plain");
	const std::string names[] = {dir + "/gz.rawlog", dir + "/plain.rawlog"};
	const RawlogCompression kinds[] = {RawlogCompression::Gzip, RawlogCompression::None};
	for (int i = 0; i < 2; ++i)
	{
		RawlogWriter w(names[i], false, kinds[i]);
		for (std::size_t k = 0; k < 3; ++k) w.writeFrame(testFrame(k, 0.1 * static_cast<double>(k)));
		w.commit();
	}
	unsigned char magic[2][2] = {};
	for (int i = 0; i < 2; ++i) std::ifstream(names[i], std::ios::binary).read(reinterpret_cast<char*>(magic[i]), 2);
	EXPECT_TRUE(magic[0][0] == 0x1f && magic[0][1] == 0x8b);  // gzip
	EXPECT_FALSE(magic[1][0] == 0x1f && magic[1][1] == 0x8b);
	const auto gz = readFrames(names[0]), plain = readFrames(names[1]);
	ASSERT_EQ(plain.size(), 3u);
	ASSERT_EQ(gz.size(), plain.size());
	for (std::size_t k = 0; k < gz.size(); ++k)
	{
		EXPECT_EQ(plain[k].t, gz[k].t);
		expectSameImage(gz[k].image, plain[k].image);
		ASSERT_EQ(plain[k].scan.size(), gz[k].scan.size());
		for (std::size_t p = 0; p < gz[k].scan.size(); ++p) EXPECT_EQ(plain[k].scan[p].z, gz[k].scan[p].z);
	}
	EXPECT_EQ(parseRawlogCompression("none", "--x"), RawlogCompression::None);
	EXPECT_THROW(parseRawlogCompression("zstd", "--x"), InputError);
}
