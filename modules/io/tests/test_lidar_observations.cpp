// Scans with per-point time and ring, cameras with lens distortion: rawlog round trips, ring
// numbering, and real MRPT Velodyne recordings.
#include "io_test_util.h"

#include <vlo/io/frame_observations.h>
#include <vlo/io/lidar_observations.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <map>

using namespace vlo;
using namespace vlo::io;
using namespace vlo::test;

namespace
{
/// A 16-ring scan: ring r at elevation -15 + 2r degrees, azimuth sweeping with time over 0.1 s.
PointCloud ringScan(std::size_t per_ring = 36)
{
	PointCloud c;
	c.has_time = c.has_ring = true;
	for (std::size_t k = 0; k < per_ring; ++k)
		for (std::uint16_t r = 0; r < 16; ++r)
		{
			const double az = 2 * M_PI * k / per_ring, el = (-15.0 + 2.0 * r) * M_PI / 180, range = 10.0 + r;
			LidarPoint p;
			p.x = float(range * std::cos(el) * std::cos(az));
			p.y = float(range * std::cos(el) * std::sin(az));
			p.z = float(range * std::sin(el));
			p.intensity = float(r * 10 + k % 7);
			p.time = float(-0.05 + 0.1 * k / per_ring);
			p.ring = r;
			c.push_back(p);
		}
	return c;
}

void writeRawlog(const std::string& path, const std::vector<Frame>& frames, bool external_images)
{
	RawlogWriter w(path, external_images);
	for (const auto& f : frames) w.writeFrame(f);
	w.commit();
}

std::map<std::uint16_t, double> meanElevationPerRing(const PointCloud& c)
{
	std::map<std::uint16_t, std::pair<double, int>> acc;
	for (const auto& p : c)
	{
		acc[p.ring].first += std::atan2(p.z, std::hypot(p.x, p.y));
		++acc[p.ring].second;
	}
	std::map<std::uint16_t, double> mean;
	for (const auto& [r, a] : acc) mean[r] = a.first / a.second;
	return mean;
}
}  // namespace

TEST(LidarObservations, TimeAndRingSurviveARawlogWithTheScanStampedApartFromTheImage)
{
	const std::string dir = freshDir(), path = dir + "/x.rawlog";
	Frame image = testFrame(0, 10.0), scan = testFrame(0, 10.02);
	image.has_scan = false;
	scan.has_image = false;
	scan.scan = ringScan();
	writeRawlog(path, {image, scan}, false);
	const auto frames = readFrames(path);
	ASSERT_EQ(frames.size(), 1u);
	const PointCloud& got = frames[0].scan;
	EXPECT_DOUBLE_EQ(frames[0].t, 10.0);  // the frame has the image's time
	ASSERT_TRUE(got.has_time);
	ASSERT_TRUE(got.has_ring);
	ASSERT_EQ(got.size(), scan.scan.size());
	for (std::size_t i = 0; i < got.size(); ++i)
	{
		const auto &a = scan.scan[i], &b = got[i];
		EXPECT_EQ(a.x, b.x);
		EXPECT_EQ(a.y, b.y);
		EXPECT_EQ(a.z, b.z);
		EXPECT_EQ(a.ring, b.ring);
		EXPECT_EQ(std::lround(a.intensity), b.intensity);  // 8-bit intensity in CObservationVelodyneScan
		// Relative to the frame's (image's) time now: 0.02 s later than relative to the scan's stamp.
		EXPECT_NEAR(b.time, a.time + 0.02, 1.1e-6);  // CObservationVelodyneScan stores 1 us
	}
}

TEST(LidarObservations, ScanWithoutTimeOrRingStaysAPointCloudWithFloatIntensity)
{
	Frame f = testFrame(0, 1.0);
	auto obs = toScanObservation(f, "LIDAR");
	EXPECT_STREQ(obs->GetRuntimeClass()->className, "mrpt::obs::CObservationPointCloud");
	const ScanReading r = readScanObservation(*obs, "here");
	EXPECT_FALSE(r.points.has_time);
	EXPECT_FALSE(r.points.has_ring);
	ASSERT_EQ(r.points.size(), f.scan.size());
	EXPECT_FLOAT_EQ(r.points[3].intensity, f.scan[3].intensity);
	f.scan.has_ring = true;  // ring alone is enough to need the per-point class
	EXPECT_STREQ(toScanObservation(f, "LIDAR")->GetRuntimeClass()->className, "mrpt::obs::CObservationVelodyneScan");
}

TEST(LidarObservations, RingsAreNumberedBottomUpWhateverTheDriversOrder)
{
	const PointCloud truth = ringScan();
	PointCloud up = truth;  // already bottom-up, with a missing ring 5: ids kept
	up.erase(std::remove_if(up.begin(), up.end(), [](const LidarPoint& p) { return p.ring == 5; }), up.end());
	PointCloud kept = up;
	orderRingsByElevation(kept);
	for (std::size_t i = 0; i < up.size(); ++i) ASSERT_EQ(kept[i].ring, up[i].ring);

	PointCloud down = up;  // Ouster: 0 is the top beam; the gap is kept
	for (auto& p : down) p.ring = static_cast<std::uint16_t>(15 - p.ring);
	orderRingsByElevation(down);
	for (std::size_t i = 0; i < up.size(); ++i) ASSERT_EQ(down[i].ring, up[i].ring);

	PointCloud fired = truth;  // Velodyne firing order: -15, 1, -13, 3, ... degrees
	const auto firing = [](std::uint16_t r) { return static_cast<std::uint16_t>(r < 8 ? 2 * r : 2 * (r - 8) + 1); };
	for (auto& p : fired) p.ring = firing(p.ring);
	orderRingsByElevation(fired);
	for (std::size_t i = 0; i < truth.size(); ++i) ASSERT_EQ(fired[i].ring, truth[i].ring);
}

TEST(LidarObservations, DistortionModelsSurviveARawlog)
{
	const std::string dir = freshDir(), path = dir + "/x.rawlog";
	Frame a = testFrame(0, 0.0), b = testFrame(1, 0.1);
	a.rig.camera.distortion = mrpt::img::DistortionModel::plumb_bob;
	a.rig.camera.dist = {-0.28, 0.07, 1e-4, -2e-4, 0.01, 0.002, -0.003, 0.0004};  // rational polynomial
	b.rig.camera.distortion = mrpt::img::DistortionModel::kannala_brandt;
	b.rig.camera.dist = {0.01, -0.005, 0, 0, 0.002, -0.0007, 0, 0};  // equidistant k1 k2 k3 k4
	writeRawlog(path, {a, b}, true);
	const auto frames = readFrames(path);
	ASSERT_EQ(frames.size(), 2u);
	for (int k = 0; k < 2; ++k)
	{
		const PinholeCamera &want = (k ? b : a).rig.camera, &got = frames[k].rig.camera;
		EXPECT_EQ(got.distortion, want.distortion);
		EXPECT_EQ(got.dist, want.dist);
		EXPECT_TRUE(got.distorted());
		EXPECT_EQ(got.fx, want.fx);
	}
}

TEST(LidarObservations, RealVlp16PacketsDecodeWithTimeAndBottomUpRings)
{
	const std::string path = std::string(VLO_SHARED_DATA) + "/mrpt_samples/test_velodyne_VLP16.rawlog";
	mrpt::io::CFileGZInputStream f(path);
	auto ar = mrpt::serialization::archiveFrom(f);
	auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(ar.ReadObject());
	ASSERT_TRUE(obs);
	ASSERT_TRUE(obs->point_cloud.size() == 0 && !obs->scan_packets.empty());  // raw packets only
	const ScanReading r = readScanObservation(*obs, path);
	EXPECT_GT(r.points.size(), 10000u);
	ASSERT_TRUE(r.points.has_time);
	ASSERT_TRUE(r.points.has_ring);
	float t_min = 1, t_max = -1;
	for (const auto& p : r.points) t_min = std::min(t_min, p.time), t_max = std::max(t_max, p.time);
	EXPECT_GE(t_min, 0.0f);  // the stamp is the first firing
	EXPECT_NEAR(t_max, 0.1, 0.01);  // one revolution at 10 Hz
	// VLP-16: 16 beams from -15 to +15 degrees, 2 degrees apart, numbered bottom-up.
	const auto elevation = meanElevationPerRing(r.points);
	ASSERT_EQ(elevation.size(), 16u);
	for (const auto& [ring, e] : elevation) EXPECT_NEAR(e * 180 / M_PI, -15.0 + 2.0 * ring, 0.5) << "ring " << ring;
}

TEST(LidarObservations, ClassesWithoutPointsAreRefusedByName)
{
	// Written by a newer MRPT: a CObservationRotatingScan, which MRPT 2.5 cannot read.
	const std::string path = std::string(VLO_SHARED_DATA) + "/mrpt_samples/rot_scan_velodyne.rawlog";
	RawlogReaderOptions opt;
	opt.lidar_label = "Velodyne1_SCAN";
	opt.need_camera = false;
	expectInputError([&] { readFrames(path, opt); }, {path, "CObservationRotatingScan"});
	auto img = toImageObservation(testFrame(0, 0), "LIDAR");
	expectInputError([&] { readScanObservation(*img, "scan.rawlog"); }, {"scan.rawlog", "CObservationImage"});
}
