#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/io/pcd.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>

using namespace vlo;
using namespace vlo::io;

namespace
{
std::string tmpPath(const std::string& name) { return ::testing::TempDir() + "vlo_pcd_" + name; }

PointCloud randomCloud(size_t n)
{
	std::mt19937 rng(7);
	std::uniform_real_distribution<float> u(-80.f, 80.f), i(0.f, 1.f);
	PointCloud c(n);
	for (auto& p : c) p = {u(rng), u(rng), u(rng) * 1e-3f, i(rng)};
	c.push_back({1e-7f, -3.4e38f, 123456.789f, 255.f});  // extremes of float32
	return c;
}

void expectSame(const PointCloud& a, const PointCloud& b)
{
	ASSERT_EQ(a.size(), b.size());
	for (size_t k = 0; k < a.size(); ++k)
	{
		EXPECT_EQ(a[k].x, b[k].x) << k;
		EXPECT_EQ(a[k].y, b[k].y) << k;
		EXPECT_EQ(a[k].z, b[k].z) << k;
		EXPECT_EQ(a[k].intensity, b[k].intensity) << k;
	}
}

void writeRaw(const std::string& path, const std::string& bytes)
{
	std::ofstream(path, std::ios::binary) << bytes;
}

/// Expects readPcd(path) to throw InputError whose message names the file and contains `what`.
void expectError(const std::string& path, const std::string& what)
{
	try
	{
		readPcd(path);
		FAIL() << "no error for " << what;
	}
	catch (const InputError& e)
	{
		const std::string msg = e.what();
		EXPECT_NE(msg.find(path), std::string::npos) << msg;
		EXPECT_NE(msg.find(what), std::string::npos) << msg;
	}
}

pcl::PointCloud<pcl::PointXYZI> toPcl(const PointCloud& cloud)
{
	pcl::PointCloud<pcl::PointXYZI> pc;
	for (const auto& p : cloud)
	{
		pcl::PointXYZI q;
		q.x = p.x, q.y = p.y, q.z = p.z, q.intensity = p.intensity;
		pc.push_back(q);
	}
	return pc;
}

const std::string kHead = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n";
}  // namespace

TEST(Pcd, BinaryRoundTripIsExact)
{
	const auto cloud = randomCloud(5000);
	const auto path = tmpPath("bin.pcd");
	writePcd(path, cloud, PcdFormat::Binary);
	expectSame(cloud, readPcd(path));
	std::ifstream in(path, std::ios::binary | std::ios::ate);
	EXPECT_GT(size_t(in.tellg()), cloud.size() * 16);  // header + 16 bytes a point
	EXPECT_LT(size_t(in.tellg()), cloud.size() * 16 + 400);
}

TEST(Pcd, BinaryIsWhatPclWrites)
{
	const auto cloud = randomCloud(70000);  // more than one slice
	const auto pc = toPcl(cloud);
	const auto ours = tmpPath("ours.pcd"), pcls = tmpPath("pcl.pcd");
	writePcd(ours, cloud, PcdFormat::Binary);
	ASSERT_EQ(pcl::PCDWriter().writeBinary(pcls, pc), 0);
	auto bytes = [](const std::string& p) {
		std::ifstream in(p, std::ios::binary);
		return std::string(std::istreambuf_iterator<char>(in), {});
	};
	const std::string a = bytes(ours), b = bytes(pcls);
	EXPECT_EQ(a.size(), b.size());
	EXPECT_TRUE(a == b);
}

TEST(Pcd, AsciiRoundTripIsExact)
{
	const auto cloud = randomCloud(500);
	const auto path = tmpPath("ascii.pcd");
	writePcd(path, cloud, PcdFormat::Ascii);
	expectSame(cloud, readPcd(path));
}

TEST(Pcd, ReadsBinaryCompressed)
{
	const auto pc = toPcl(randomCloud(1000));
	const auto path = tmpPath("compressed.pcd");
	ASSERT_EQ(pcl::PCDWriter().writeBinaryCompressed(path, pc), 0);
	expectSame(randomCloud(1000), readPcd(path));
}

TEST(Pcd, EmptyCloudRoundTrips)
{
	const auto path = tmpPath("empty.pcd");
	writePcd(path, {}, PcdFormat::Binary);
	EXPECT_TRUE(readPcd(path).empty());
}

TEST(Pcd, ReadsPclStyleBinaryWithOtherFieldsAndDoubles)
{
	// x y z as F8, a U2 ring between them, an rgb F4 with COUNT 1, and intensity as U1.
	std::string s = "# written by some tool\nVERSION .7\nFIELDS x ring y z rgb intensity\nSIZE 8 2 8 8 4 1\n"
					"TYPE F U F F F U\nCOUNT 1 1 1 1 1 1\nWIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\n"
					"DATA binary\n";
	auto put = [&](auto v) { s.append(reinterpret_cast<const char*>(&v), sizeof v); };
	put(1.5), put(std::uint16_t(7)), put(-2.25), put(3.0), put(0.f), put(std::uint8_t(200));
	put(std::nan("")), put(std::uint16_t(8)), put(1.0), put(1.0), put(0.f), put(std::uint8_t(1));  // NaN: dropped
	const auto path = tmpPath("pcl.pcd");
	writeRaw(path, s);
	const auto c = readPcd(path);
	ASSERT_EQ(c.size(), 1u);
	EXPECT_EQ(c[0].x, 1.5f);
	EXPECT_EQ(c[0].y, -2.25f);
	EXPECT_EQ(c[0].z, 3.0f);
	EXPECT_EQ(c[0].intensity, 200.f);
}

TEST(Pcd, ReadsAsciiWithoutIntensityAndSkipsNan)
{
	const auto path = tmpPath("noint.pcd");
	writeRaw(path, kHead + "POINTS 2\nDATA ascii\n1 2 3\nnan nan nan\n");
	const auto c = readPcd(path);
	ASSERT_EQ(c.size(), 1u);
	EXPECT_EQ(c[0].z, 3.f);
	EXPECT_EQ(c[0].intensity, 0.f);
}

TEST(Pcd, MalformedFilesGiveClearErrors)
{
	const auto p = tmpPath("bad.pcd");
	writeRaw(p, "hello world\n");
	expectError(p, "line 1: 'hello' is not a PCD header keyword");
	writeRaw(p, kHead + "POINTS 2\n");
	expectError(p, "no DATA line");
	writeRaw(p, "FIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2 3\n");
	expectError(p, "SIZE, TYPE or COUNT");
	writeRaw(p, "FIELDS x y\nSIZE 4 4\nTYPE F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2\n");
	expectError(p, "lacks x, y or z");
	writeRaw(p, "FIELDS x y z\nSIZE 4 4 2\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2 3\n");
	expectError(p, "SIZE 2 is invalid for TYPE F");
	writeRaw(p, kHead + "POINTS 3\nDATA ascii\n");
	expectError(p, "POINTS 3 differs from WIDTH x HEIGHT = 2");
	writeRaw(p, kHead + "POINTS 2\nDATA binary_compressed\n");
	expectError(p, "malformed or truncated PCD data");
	writeRaw(p, kHead + "POINTS 2\nDATA ascii\n1 2 3\n");
	expectError(p, "malformed or truncated PCD data");
	writeRaw(p, kHead + "POINTS 2\nDATA binary\n" + std::string(20, '\0'));
	expectError(p, "only 20 bytes follow");
	writeRaw(p, kHead + "WIDTH 3\nPOINTS 2\nDATA ascii\n");
	expectError(p, "WIDTH given twice");
	expectError(tmpPath("does_not_exist.pcd"), "cannot open file");
}

TEST(Pcd, FailedWriteLeavesNothingBehind)
{
	const std::string path = tmpPath("no_such_dir/x.pcd");
	EXPECT_THROW(writePcd(path, randomCloud(10)), InputError);
	EXPECT_FALSE(std::ifstream(path).good());
	EXPECT_FALSE(std::ifstream(path + ".partial").good());
}
