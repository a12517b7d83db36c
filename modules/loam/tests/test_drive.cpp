// Short synthetic drives through an urban world: the trajectory must stay close to the truth.
#include <gtest/gtest.h>
#include <vlo/core/sweep_times.h>
#include <vlo/loam/lidar_odometry.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
namespace
{
struct DriveStats
{
	double final_trans_err = 0, max_trans_err = 0, max_rot_err_deg = 0, length = 0;
	double mean_ms = 0, max_ms = 0;
	int not_ok = 0;
	std::size_t map_edge_points = 0;  ///< the most the edge map held
	int mapping_edges = 0;  ///< the most edge matches of one frame's scan-to-map
};

// `moving`: each sweep is measured while the sensor moves from the previous frame's pose to this
// one's (the frame's pose is that at the end of the sweep), as a real spinning LiDAR does; the
// drive then starts one step into the path, already at speed.
// `fields`: the scans carry the sensor's ring ids and/or per-point times.
struct Fields
{
	bool rings = false, times = false;
	bool azimuth_times = false;  ///< times from the azimuth ([lidar] point_times) instead of the sensor's
};
DriveStats drive(const LidarModel& lidar, const LoamOptions& opt, const Path& path, double step, int frames,
	unsigned seed, bool verbose, bool moving = false, Fields fields = {})
{
	const World world = urbanWorld(path, seed);
	std::mt19937 rng(seed);
	LidarOdometry lo(opt);
	DriveStats st;
	const double s0 = moving ? step : 0.0;
	const Eigen::Isometry3d T0 = lidarPoseAt(path, s0);
	for (int i = 0; i < frames; ++i)
	{
		const Eigen::Isometry3d truth = lidarPoseAt(path, s0 + i * step);
		PointCloud pc = moving ? scan(world, lidar, lidarPoseAt(path, s0 + (i - 1) * step), truth, &rng) : scan(world, lidar, truth, &rng);
		pc.has_ring = fields.rings, pc.has_time = fields.times;
		// The synthetic sweep turns clockwise from behind and ends (where it started) at the frame's time.
		if (fields.azimuth_times) setTimesFromAzimuth(pc, SpinningSweep{true, lidar.period, M_PI, 1.0});
		const LidarOdometryResult r = lo.process(0.1 * i, pc, std::nullopt);
		const Eigen::Isometry3d rel = T0.inverse() * truth;
		const double et = translationError(r.pose, rel), er = rotationErrorDeg(r.pose, rel);
		const Eigen::Vector3d dr = Eigen::AngleAxisd(rel.linear().transpose() * r.pose.linear()).axis() *
			(Eigen::AngleAxisd(rel.linear().transpose() * r.pose.linear()).angle() * 180 / M_PI);
		st.max_trans_err = std::max(st.max_trans_err, et);
		st.max_rot_err_deg = std::max(st.max_rot_err_deg, er);
		st.final_trans_err = et;
		if (i > 0) st.mean_ms += r.ms.total() / (frames - 1), st.max_ms = std::max(st.max_ms, r.ms.total());
		if (r.status != LidarFrameStatus::Ok && i > 0) ++st.not_ok;
		st.map_edge_points = std::max(st.map_edge_points, r.map_edge_points);
		st.mapping_edges = std::max(st.mapping_edges, r.mapping.n_edges);
		if (verbose)
			std::printf("%3d %-12s et %.3f er %.3f (rpy %.3f %.3f %.3f) | pts %zu sharp %zu flat %zu lf %zu | odo %d/%d it %d rms %.3f | map "
						"%d/%d it %d rms %.3f mineig %.0f | ms feat %.1f odo %.1f map %.1f tot %.1f | "
						"map %zu+%zu %s\n",
				i, toString(r.status), et, er, dr.x(), dr.y(), dr.z(), r.n_valid, r.n_sharp, r.n_flat, r.n_less_flat, r.odometry.n_edges,
				r.odometry.n_planes, r.odometry.iterations, r.odometry.rms, r.mapping.n_edges, r.mapping.n_planes,
				r.mapping.iterations, r.mapping.rms, r.mapping.degeneracy.min_eigenvalue, r.ms.ms("features"),
				r.ms.ms("odometry"), r.ms.ms("mapping"), r.ms.total(), r.map_edge_points, r.map_plane_points,
				r.reason.c_str());
	}
	st.length = step * (frames - 1);
	return st;
}

Path curvyPath()
{
	Path p;
	p.add(20, 0.0);
	p.add(25, 1.0 / 30);  // a 48 deg left bend
	p.add(30, 0.0);
	p.add(25, -1.0 / 40);
	p.add(100, 0.0);
	return p;
}

/// Every frame registered, the largest errors below the bounds.
void expectTracked(const DriveStats& st, double max_trans_err, double max_rot_err_deg)
{
	EXPECT_EQ(st.not_ok, 0);
	EXPECT_LT(st.max_trans_err, max_trans_err);
	EXPECT_LT(st.max_rot_err_deg, max_rot_err_deg);
}

/// The curvy path, 40 frames 1 m apart, ranges with 1 cm noise; prints its errors as `name`.
DriveStats urbanDrive(const char* name, LidarModel m, const LoamOptions& o, unsigned seed)
{
	m.noise_sigma = 0.01;
	const DriveStats st = drive(m, o, curvyPath(), 1.0, 40, seed, std::getenv("VLO_VERBOSE") != nullptr);
	std::printf("%s: %.0f m, final err %.3f m (%.2f%%), max err %.3f m, max rot err %.3f deg, %.1f ms/frame (max %.1f)\n",
		name, st.length, st.final_trans_err, 100 * st.final_trans_err / st.length, st.max_trans_err, st.max_rot_err_deg,
		st.mean_ms, st.max_ms);
	return st;
}
}  // namespace

TEST(Drive, Hdl64Urban) { expectTracked(urbanDrive("HDL-64", hdl64(), hdl64Options(), 7), 0.05, 0.1); }

// `[loam.mapping] edges`: scan-to-map with edges and planes (A-LOAM, on), planes alone and no edge map
// (off), or edges only where the planes leave the translation weak (auto: never in this street).
TEST(Drive, Hdl64UrbanWithAndWithoutEdgesInScanToMap)
{
	for (const char* edges : {"on", "off", "auto"})
	{
		LoamOptions o = hdl64Options();
		o.mapping.edges = edges;
		const DriveStats st = urbanDrive((std::string("HDL-64 edges ") + edges).c_str(), hdl64(), o, 7);
		expectTracked(st, 0.05, 0.1);
		const std::string e = edges;
		EXPECT_EQ(st.mapping_edges > 20, e == "on");
		EXPECT_EQ(st.map_edge_points > 1000, e != "off");
		if (e != "on")
		{
			EXPECT_EQ(st.mapping_edges, 0);
		}
	}
}

TEST(Drive, Vlp16Urban) { expectTracked(urbanDrive("VLP-16", vlp16(), vlp16Options(), 11), 0.1, 0.2); }

TEST(Drive, DeskewUndoesTheMotionDuringTheSweep)
{
	// 15 m/s through the bends: without deskewing, each sweep is smeared by 1.5 m and 3 deg. Deskewed
	// with times from the azimuth, or with the sensor's times (seconds before the frame's time, the
	// end of the sweep): the times alone undo the motion.
	LidarModel m = vlp16();
	m.noise_sigma = 0.01;
	const LoamOptions o = vlp16Options();
	const DriveStats raw = drive(m, o, curvyPath(), 1.5, 30, 13, false, true);
	const DriveStats timed = drive(m, o, curvyPath(), 1.5, 30, 13, false, true, {false, true});
	const DriveStats fixed =
		drive(m, o, curvyPath(), 1.5, 30, 13, std::getenv("VLO_VERBOSE") != nullptr, true, {false, false, true});
	std::printf("moving sweeps over %.0f m: max error %.3f m / %.3f deg raw, %.3f m / %.3f deg deskewed from the azimuth, "
				"%.3f m / %.3f deg with point times\n",
		raw.length, raw.max_trans_err, raw.max_rot_err_deg, fixed.max_trans_err, fixed.max_rot_err_deg, timed.max_trans_err,
		timed.max_rot_err_deg);
	for (const DriveStats* d : {&fixed, &timed})
	{
		EXPECT_LT(d->max_trans_err, 0.5 * raw.max_trans_err);
		EXPECT_LT(d->max_trans_err, 0.2);
		EXPECT_LT(d->max_rot_err_deg, 0.5 * raw.max_rot_err_deg);
	}
}

TEST(Drive, RingIdsServeABeamLayoutWithoutRingModel)
{
	// 32 beams unevenly spread over -25..+12 deg (no INI table matches it) read with a VLP-16 INI:
	// with the sensor's ring ids LOAM needs no elevation table.
	LidarModel m = vlp16();
	m.elevations_deg.clear();
	for (int k = 0; k < 32; ++k) m.elevations_deg.push_back(-25.0 + 37.0 * std::pow(k / 31.0, 0.8));
	m.noise_sigma = 0.01;
	const DriveStats ids = drive(m, vlp16Options(), curvyPath(), 1.0, 30, 17, std::getenv("VLO_VERBOSE") != nullptr, false, {true, false});
	const DriveStats table = drive(m, vlp16Options(), curvyPath(), 1.0, 30, 17, false);
	std::printf("unknown 32-beam layout over %.0f m, VLP-16 ring model: max error %.3f m / %.3f deg with ring ids, %.3f m / %.3f deg "
				"from elevations\n",
		ids.length, ids.max_trans_err, ids.max_rot_err_deg, table.max_trans_err, table.max_rot_err_deg);
	expectTracked(ids, 0.1, 0.2);
}
TEST(Drive, RingIdsMatchLikeTheRingModel)
{
	// The same HDL-64 drive read with the ring model's elevation table and with the sensor's ring ids.
	// Between two sweeps a point ahead drops to a lower beam: the scan-to-scan search must start on the
	// reference ring at the point's elevation, not on the point's own beam (which matched ground points
	// a beam too far and shortened every step: 0.42 m final error against 0.085 m, now equal).
	// Scan-to-scan alone, where the search start matters (scan-to-map searches a kd-tree).
	LidarModel m = hdl64();
	m.noise_sigma = 0.01;
	LoamOptions o = hdl64Options();
	o.mapping.enabled = false;
	const DriveStats table = drive(m, o, curvyPath(), 1.2, 40, 7, false);
	const DriveStats ids = drive(m, o, curvyPath(), 1.2, 40, 7, std::getenv("VLO_VERBOSE") != nullptr, false, {true, false});
	std::printf("HDL-64 over %.0f m: final error %.4f m with the ring model, %.4f m with ring ids (max %.4f / %.4f m)\n", ids.length,
		table.final_trans_err, ids.final_trans_err, table.max_trans_err, ids.max_trans_err);
	EXPECT_EQ(ids.not_ok, 0);
	EXPECT_LT(ids.final_trans_err, 1.15 * table.final_trans_err + 0.002);
	EXPECT_LT(ids.max_trans_err, 1.15 * table.max_trans_err + 0.002);
}
}  // namespace vlo::loam::test
