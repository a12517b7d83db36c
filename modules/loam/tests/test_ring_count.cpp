// The rings a scan has, as its data tells, and the check that refuses an INI's ring model that
// contradicts them: synthetic VLP-16 / HDL-64E sweeps (known answer) and real KITTI HDL-64E scans.
#include "kitti_data.h"
#include "synthetic_world.h"

#include <vlo/core/error.h>
#include <vlo/loam/ring_count.h>
#include <vlo/loam/rings.h>

#include <gtest/gtest.h>

namespace vlo::loam
{
using namespace test;
namespace
{
PointCloud urbanSweep(const LidarModel& m)
{
	Path p;
	p.add(100, 0.0);
	std::mt19937 rng(3);
	Eigen::Isometry3d pose = p.at(20);
	pose.translation().z() = 1.73;  // on a car's roof
	return scan(urbanWorld(p, 3), m, pose, &rng);
}

ScanOptions vlp16Options()
{
	ScanOptions o;
	o.ring_model = "uniform";
	o.n_rings = 16;
	o.vfov_min_deg = -15;
	o.vfov_max_deg = 15;
	return o;
}

ScanOptions hdl64Options()
{
	ScanOptions o;
	o.ring_model = "hdl64";
	return o;
}

/// The error message of three scans through a check, "" when it passes, "not judged" when they cannot tell.
std::string judge(const ScanOptions& o, const PointCloud& scan)
{
	RingModelCheck check("my.ini", o, RingModel(o).elevationsDeg());
	try
	{
		for (int i = 0; i < 3; ++i) check.observe(scan);
	}
	catch (const InputError& e)
	{
		return e.what();
	}
	return check.done() ? "" : "not judged";
}
}  // namespace

TEST(RingCount, SyntheticSweepsByElevation)
{
	LidarModel vlp = vlp16(), hdl = hdl64();
	vlp.noise_sigma = hdl.noise_sigma = 0.02;
	const RingEvidence v = countRings(urbanSweep(vlp)), h = countRings(urbanSweep(hdl));
	EXPECT_EQ(v.rings, 16);
	EXPECT_NEAR(v.spacing_deg, 2.0, 0.05);
	EXPECT_NEAR(h.spacing_deg, 26.33 / 63, 0.1);
	const int n = h.rings;
	EXPECT_GE(n, 62);
	EXPECT_LE(n, 64);
}

TEST(RingCount, RingFieldWhenTheScanHasIt)
{
	PointCloud pc;
	pc.has_ring = true;
	for (int i = 0; i < 6000; ++i) pc.push_back({10.0f, 0.0f, 0.0f, 0.0f, 0.0f, static_cast<std::uint16_t>(i % 32)});
	EXPECT_EQ(countRings(pc).rings, 32);  // all at one elevation: only the ring ids tell
}

TEST(RingCount, SparseScanTellsNothing)
{
	PointCloud hdl = urbanSweep(hdl64());
	PointCloud thin;
	for (std::size_t i = 0; i < hdl.size(); i += 200) thin.push_back(hdl[i]);
	EXPECT_EQ(countRings(thin).rings, 0);
	EXPECT_EQ(judge(vlp16Options(), thin), "not judged");
}

TEST(RingCount, ModelContradictingTheDataIsRefused)
{
	const PointCloud hdl = urbanSweep(hdl64()), vlp = urbanSweep(vlp16());
	EXPECT_EQ(judge(hdl64Options(), hdl), "");
	EXPECT_EQ(judge(vlp16Options(), vlp), "");
	const std::string wrong16 = judge(vlp16Options(), hdl);
	EXPECT_NE(wrong16.find("my.ini: [loam.scan] ring model uniform (16 rings) but the scans have 6"), std::string::npos)
		<< wrong16;
	EXPECT_NE(wrong16.find("ring_model = hdl64"), std::string::npos) << wrong16;
	const std::string wrong64 = judge(hdl64Options(), vlp);
	EXPECT_NE(wrong64.find("ring model hdl64 (64 rings) but the scans have 16 rings"), std::string::npos) << wrong64;
	EXPECT_NE(wrong64.find("ini/vlp16.ini"), std::string::npos) << wrong64;
	EXPECT_EQ(wrong64.find('\n'), std::string::npos);
}

TEST(RingCount, KittiHdl64Scans)
{
	const auto root = sharedData("kitti_odometry_snippets.tar.xz", "kitti_odometry_snippets",
		"'*velodyne*' '*poses*' '*.txt'", "poses/08.txt");
	if (!std::filesystem::exists(root / "poses" / "08.txt"))
		GTEST_SKIP() << "real-data test not run: no kitti_odometry_snippets.tar.xz in " VLO_SHARED_DATA;
	for (const std::string seq : {"00", "04", "06", "08"})
		for (const std::string f : {"000000.bin", "000009.bin"})
		{
			const PointCloud pc = readKittiBin(root / "sequences" / seq / "velodyne" / f);
			const int n = countRings(pc).rings;
			EXPECT_GE(n, 58) << seq << "/" << f;
			EXPECT_LE(n, 72) << seq << "/" << f;
			EXPECT_EQ(judge(hdl64Options(), pc), "") << seq;
			EXPECT_NE(judge(vlp16Options(), pc), "") << seq;
		}
}
}  // namespace vlo::loam
