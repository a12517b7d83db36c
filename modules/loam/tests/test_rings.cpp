// Ring assignment from elevation, sweep timing from azimuth, dropping of invalid returns.
#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/loam/rings.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
LidarPoint at(double range, double az_deg, double el_deg)
{
	const double a = az_deg * M_PI / 180, e = el_deg * M_PI / 180;
	return LidarPoint{static_cast<float>(range * std::cos(e) * std::cos(a)), static_cast<float>(range * std::cos(e) * std::sin(a)),
		static_cast<float>(range * std::sin(e)), 0.f};
}
}  // namespace

TEST(Rings, FastAtan2IsAccurate)
{
	double worst = 0;
	for (int i = 0; i < 3600; ++i)
		for (double r : {0.01, 1.0, 80.0})
		{
			const double a = -M_PI + 2 * M_PI * i / 3600.0;
			const float y = static_cast<float>(r * std::sin(a)), x = static_cast<float>(r * std::cos(a));
			worst = std::max(worst, std::abs(std::remainder(fastAtan2(y, x) - std::atan2(y, x), 2 * M_PI)));
		}
	EXPECT_LT(worst, 2e-5);
	EXPECT_EQ(fastAtan2(0.f, 0.f), 0.f);
}

TEST(Rings, Uniform16Beams)
{
	const RingModel m(vlp16Options().scan);
	ASSERT_EQ(m.numRings(), 16);
	for (int k = 0; k < 16; ++k)
	{
		const double e = -15.0 + 2.0 * k;
		for (double de : {-0.9, 0.0, 0.9})  // anywhere within a beam's half spacing
		{
			if (std::abs(e + de) > 15.5) continue;  // beyond the field of view
			const LidarPoint p = at(20.0, 33.0, e + de);
			EXPECT_EQ(m.ringOf(p.z, std::hypot(p.x, p.y)), k) << "elevation " << e + de;
		}
	}
	const LidarPoint below = at(20, 0, -15.6), above = at(20, 0, 15.6), edge = at(20, 0, -15.4);
	EXPECT_EQ(m.ringOf(below.z, std::hypot(below.x, below.y)), -1);
	EXPECT_EQ(m.ringOf(above.z, std::hypot(above.x, above.y)), -1);
	EXPECT_EQ(m.ringOf(edge.z, std::hypot(edge.x, edge.y)), 0);  // within the 0.5 deg margin
	EXPECT_EQ(m.ringOf(0.f, 0.f), -1);
}

TEST(Rings, Uniform32Beams)
{
	// HDL-32E: 32 beams from -30.67 to +10.67 deg.
	ScanOptions o;
	o.n_rings = 32;
	o.vfov_min_deg = -30.67;
	o.vfov_max_deg = 10.67;
	const RingModel m(o);
	ASSERT_EQ(m.numRings(), 32);
	const double step = (10.67 + 30.67) / 31;
	for (int k = 0; k < 32; ++k)
	{
		const LidarPoint p = at(25.0, -70.0, -30.67 + step * k + 0.3 * step);
		EXPECT_EQ(m.ringOf(p.z, std::hypot(p.x, p.y)), k);
	}
}

TEST(Rings, Hdl64TwoBlocks)
{
	const RingModel m(hdl64Options().scan);
	ASSERT_EQ(m.numRings(), 64);
	const std::vector<double> e = RingModel::hdl64Elevations();
	std::vector<double> sorted = e;
	std::sort(sorted.begin(), sorted.end());
	for (int k = 0; k < 64; ++k)
	{
		const LidarPoint p = at(30.0, -120.0, sorted[k]);
		EXPECT_EQ(m.ringOf(p.z, std::hypot(p.x, p.y)), k) << sorted[k];
	}
	// The two blocks' different spacing: 1/3 deg above -8.33 deg, 1/2 deg below -8.83 deg.
	const LidarPoint upper = at(30, 0, 2.0 - 31 / 3.0 + 0.15), lower = at(30, 0, -8.83 - 0.2);
	EXPECT_EQ(m.ringOf(upper.z, std::hypot(upper.x, upper.y)), 32);
	EXPECT_EQ(m.ringOf(lower.z, std::hypot(lower.x, lower.y)), 31);
}

TEST(Rings, ExplicitTable)
{
	ScanOptions o;
	o.ring_model = "table";
	o.elevation_table_deg = {5.0, -3.0, 1.0, -20.0};  // any order
	const RingModel m(o);
	ASSERT_EQ(m.numRings(), 4);
	EXPECT_DOUBLE_EQ(m.elevationsDeg()[0], -20.0);
	const LidarPoint p = at(10, 0, 1.2);
	EXPECT_EQ(m.ringOf(p.z, std::hypot(p.x, p.y)), 2);
}

// ringOf's lookup table must never disagree with a binary search of the beam table, least of all at
// the bounds between beams: every bound and its float neighbours, and a dense sweep.
TEST(Rings, RingOfLookupAgreesWithTheSearchEverywhere)
{
	ScanOptions table;
	table.ring_model = "table";
	table.elevation_table_deg = {5.0, -3.0, 1.0, -20.0, -19.9};
	ScanOptions hdl64;
	hdl64.ring_model = "hdl64";
	for (const ScanOptions& o : {vlp16Options().scan, hdl64, table})
	{
		const RingModel m(o);
		const auto& e = m.elevationsDeg();
		std::vector<float> bounds, ts;  // the model's: tan of the midpoints between beams
		for (std::size_t k = 0; k + 1 < e.size(); ++k)
			bounds.push_back(static_cast<float>(std::tan(0.5 * (e[k] + e[k + 1]) * (M_PI / 180.0))));
		for (float b : bounds)
		{
			for (int i = 0; i < 3; ++i) b = std::nextafter(b, -1.0f);
			for (int i = 0; i < 7; ++i, b = std::nextafter(b, 1.0f)) ts.push_back(b);
		}
		for (int i = 0; i <= 200000; ++i) ts.push_back(-1.2f + 2.4f * static_cast<float>(i) / 200000.0f);
		int in_view = 0;
		for (float t : ts)
		{
			const int r = m.ringOf(t, 1.0f);
			if (r < 0) continue;
			++in_view;
			ASSERT_EQ(r, std::upper_bound(bounds.begin(), bounds.end(), t) - bounds.begin()) << "tan(elevation) " << t;
		}
		EXPECT_GT(in_view, 1000);
	}
}

TEST(Rings, BadModelOptionsNameTheKey)
{
	ScanOptions o;
	o.ring_model = "velodyne";
	try
	{
		RingModel m(o);
		FAIL() << "no error";
	}
	catch (const InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("ring_model"), std::string::npos);
	}
	o = ScanOptions();
	o.ring_model = "table";
	EXPECT_THROW(RingModel{o}, InputError);  // empty table
}

TEST(Rings, PreprocessGroupsTimesAndDrops)
{
	ScanOptions o = vlp16Options().scan;
	ScanPreprocessor pre(o);
	PointCloud pc;
	// Column-major sweep, clockwise from azimuth 180 deg, 360 columns of 16 beams.
	for (int c = 0; c < 360; ++c)
		for (int k = 0; k < 16; ++k) pc.push_back(at(10.0 + k, 179.5 - c, -15.0 + 2 * k));
	const float nan = std::numeric_limits<float>::quiet_NaN();
	pc.push_back(LidarPoint{nan, 1, 1, 0});
	pc.push_back(LidarPoint{1, std::numeric_limits<float>::infinity(), 1, 0});
	pc.push_back(at(1.0, 0, 0));  // too close
	pc.push_back(at(500.0, 0, 0));  // too far
	pc.push_back(at(20.0, 0, 40.0));  // above the field of view
	const RingScan rs = pre.process(pc);
	EXPECT_EQ(rs.n_input, pc.size());
	EXPECT_EQ(rs.n_invalid, 2u);
	EXPECT_EQ(rs.n_out_of_range, 2u);
	EXPECT_EQ(rs.n_out_of_fov, 1u);
	ASSERT_EQ(rs.points.size(), 360u * 16u);
	for (int r = 0; r < 16; ++r)
	{
		ASSERT_EQ(rs.ringSize(r), 360u);
		for (std::size_t i = rs.ring_begin[r]; i < rs.ring_begin[r + 1]; ++i)
		{
			const ScanPoint& p = rs.points[i];
			EXPECT_EQ(p.ring, r);
			EXPECT_NEAR(p.p.norm(), 10.0 + r, 1e-3);
			// No times given: from the azimuth, a 0.1 s clockwise turn that faces forward half-way.
			EXPECT_NEAR(p.time, ((i - rs.ring_begin[r] + 0.5) / 360.0 - 0.5) * 0.1, 1e-5);
		}
	}
}

TEST(Rings, RingByRingOrderGivesTheSameRings)
{
	// KITTI stores a sweep ring by ring, each ring starting a little before or after the first point.
	PointCloud col, ringwise;
	for (int c = 0; c < 720; ++c)
		for (int k = 0; k < 16; ++k) col.push_back(at(15, 180.0 - 0.5 * c, -15.0 + 2 * k));
	for (int k = 0; k < 16; ++k)
		for (int c = 0; c < 720; ++c) ringwise.push_back(at(15, 180.0 - 0.5 * c - (k == 0 ? 0 : 0.5 * (k % 3 - 1)), -15.0 + 2 * k));
	ScanPreprocessor pre(vlp16Options().scan);
	const RingScan a = pre.process(col), b = pre.process(ringwise);
	ASSERT_EQ(a.points.size(), b.points.size());
	for (int r = 0; r < 16; ++r)
	{
		ASSERT_EQ(a.ringSize(r), b.ringSize(r));
		for (std::size_t i = b.ring_begin[r] + 1; i < b.ring_begin[r + 1]; ++i)
			EXPECT_LE(b.points[i - 1].time, b.points[i].time);  // rotated into time order
	}
}

TEST(Rings, RaycastScansLandOnTheirBeams)
{
	const Path path = [] {
		Path p;
		p.add(60, 0.0);
		return p;
	}();
	const World w = urbanWorld(path, 1);
	for (bool hdl : {false, true})
	{
		const LidarModel m = hdl ? hdl64() : vlp16();
		const PointCloud pc = scan(w, m, lidarPoseAt(path, 10));
		ScanPreprocessor pre(hdl ? hdl64Options().scan : vlp16Options().scan);
		const RingScan rs = pre.process(pc);
		EXPECT_EQ(rs.n_out_of_fov, 0u);
		EXPECT_EQ(rs.populatedRings(100), hdl ? 64 : 16);
		std::vector<double> el = m.elevations_deg;
		std::sort(el.begin(), el.end());
		for (const ScanPoint& p : rs.points)
		{
			const double e = std::atan2(p.p.z(), std::hypot(p.p.x(), p.p.y())) * 180 / M_PI;
			ASSERT_NEAR(e, el[p.ring], 0.01);
		}
	}
}

TEST(Rings, SensorRingIdsGroupABeamLayoutNoTableKnows)
{
	// 24 beams unevenly spread over -25..+12 deg, read with a VLP-16 INI (16 beams, +-15 deg).
	std::vector<double> el;
	for (int k = 0; k < 24; ++k) el.push_back(-25.0 + 37.0 * std::pow(k / 23.0, 0.7));
	PointCloud pc;
	for (int c = 0; c < 360; ++c)
		for (int k = 23; k >= 0; --k)  // top to bottom within a firing, as Velodynes fire
		{
			LidarPoint p = at(12.0, 179.5 - c, el[k]);
			p.ring = static_cast<std::uint16_t>(k);
			pc.push_back(p);
		}
	LidarPoint beyond = at(12.0, 0, 0);
	beyond.ring = kMaxRings;  // a corrupt id: dropped, not a 65536-ring scan
	pc.push_back(beyond);
	ScanPreprocessor pre(vlp16Options().scan);

	const RingScan guessed = pre.process(pc);  // without ids: elevations outside +-15.5 deg are lost
	EXPECT_FALSE(guessed.rings_from_data);
	EXPECT_GE(guessed.n_out_of_fov, 360u * 4);  // the 4 beams below -15.5 deg

	pc.has_ring = true;
	const RingScan rs = pre.process(pc);
	EXPECT_TRUE(rs.rings_from_data);
	EXPECT_EQ(rs.n_out_of_fov, 1u);
	ASSERT_EQ(rs.numRings(), 24);
	for (int r = 0; r < 24; ++r)
	{
		ASSERT_EQ(rs.ringSize(r), 360u) << "ring " << r;
		for (std::size_t i = rs.ring_begin[r]; i < rs.ring_begin[r + 1]; ++i)
		{
			const ScanPoint& p = rs.points[i];
			ASSERT_NEAR(std::atan2(p.p.z(), std::hypot(p.p.x(), p.p.y())) * 180 / M_PI, el[r], 1e-3);
			// No point times given: a Velodyne's from the azimuth, which only order the ring (seam behind).
			EXPECT_NEAR(p.time, ((i - rs.ring_begin[r] + 0.5) / 360.0 - 0.5) * 0.1, 1e-5);
		}
	}
}

TEST(Rings, SensorTimesAreSecondsFromTheFramesTime)
{
	const ScanOptions o = vlp16Options().scan;
	PointCloud pc;
	for (int c = 0; c < 36; ++c)
		for (int k = 0; k < 16; ++k)
		{
			LidarPoint p = at(10.0, 180.0 - 10 * c, -15.0 + 2 * k);
			p.time = static_cast<float>(0.1 * c / 36.0);  // a driver whose times start at 0 (the frame's time)
			pc.push_back(p);
		}
	LidarPoint stale = at(10.0, 0, 0);
	stale.time = 5.0f;  // fifty sweeps away: not a point of this sweep
	pc.push_back(stale);
	pc.has_time = true;
	const RingScan rs = ScanPreprocessor(o).process(pc);
	EXPECT_TRUE(rs.times_from_data);
	EXPECT_EQ(rs.n_invalid, 1u);
	ASSERT_EQ(rs.points.size(), 36u * 16u);
	for (int r = 0; r < 16; ++r)
		for (std::size_t i = rs.ring_begin[r]; i < rs.ring_begin[r + 1]; ++i)
			EXPECT_NEAR(rs.points[i].time, 0.1 * (i - rs.ring_begin[r]) / 36.0, 1e-6);
}
}  // namespace vlo::loam::test
