// Short synthetic drives through an urban world: the trajectory must stay close to the truth.
#include <gtest/gtest.h>
#include <vlo/loam/lidar_odometry.h>

#include <cstdio>
#include <cstdlib>

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
};

// `moving`: each sweep is measured while the sensor moves from the previous frame's pose to this
// one's (the frame's pose is that at the end of the sweep), as a real spinning LiDAR does.
DriveStats drive(const LidarModel& lidar, const LoamOptions& opt, const Path& path, double step, int frames,
	unsigned seed, bool verbose, bool moving = false)
{
	const World world = urbanWorld(path, seed);
	std::mt19937 rng(seed);
	LidarOdometry lo(opt);
	DriveStats st;
	const Eigen::Isometry3d T0 = lidarPoseAt(path, 0);
	for (int i = 0; i < frames; ++i)
	{
		const Eigen::Isometry3d truth = lidarPoseAt(path, i * step);
		const PointCloud pc = (moving && i > 0) ? scan(world, lidar, lidarPoseAt(path, (i - 1) * step), truth, &rng) : scan(world, lidar, truth, &rng);
		const LidarOdometryResult r = lo.process(0.1 * i, pc, std::nullopt);
		const Eigen::Isometry3d rel = T0.inverse() * truth;
		const double et = translationError(r.pose, rel), er = rotationErrorDeg(r.pose, rel);
		const Eigen::Vector3d dr = Eigen::AngleAxisd(rel.linear().transpose() * r.pose.linear()).axis() *
			(Eigen::AngleAxisd(rel.linear().transpose() * r.pose.linear()).angle() * 180 / M_PI);
		st.max_trans_err = std::max(st.max_trans_err, et);
		st.max_rot_err_deg = std::max(st.max_rot_err_deg, er);
		st.final_trans_err = et;
		if (i > 0) st.mean_ms += r.ms.total / (frames - 1), st.max_ms = std::max(st.max_ms, r.ms.total);
		if (r.status != FrameStatus::Ok && i > 0) ++st.not_ok;
		if (verbose)
			std::printf("%3d %-12s et %.3f er %.3f (rpy %.3f %.3f %.3f) | pts %zu sharp %zu flat %zu lf %zu | odo %d/%d it %d rms %.3f | map "
						"%d/%d it %d rms %.3f mineig %.0f | ms pre %.1f feat %.1f odo %.1f map %.1f upd %.1f tot %.1f | "
						"map %zu+%zu %s\n",
				i, toString(r.status), et, er, dr.x(), dr.y(), dr.z(), r.n_valid, r.n_sharp, r.n_flat, r.n_less_flat, r.odometry.n_edges,
				r.odometry.n_planes, r.odometry.iterations, r.odometry.rms, r.mapping.n_edges, r.mapping.n_planes,
				r.mapping.iterations, r.mapping.rms, r.mapping.degeneracy.min_eigenvalue, r.ms.preprocess, r.ms.features,
				r.ms.odometry, r.ms.mapping, r.ms.map_update, r.ms.total, r.map_edge_points, r.map_plane_points,
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
}  // namespace

TEST(Drive, Hdl64Urban)
{
	LidarModel m = hdl64();
	m.noise_sigma = 0.01;
	const DriveStats st = drive(m, hdl64Options(), curvyPath(), 1.0, 40, 7, std::getenv("VLO_VERBOSE") != nullptr);
	std::printf("HDL-64: %.0f m, final err %.3f m (%.2f%%), max err %.3f m, max rot err %.3f deg, %.1f ms/frame (max %.1f)\n",
		st.length, st.final_trans_err, 100 * st.final_trans_err / st.length, st.max_trans_err, st.max_rot_err_deg,
		st.mean_ms, st.max_ms);
	EXPECT_EQ(st.not_ok, 0);
	EXPECT_LT(st.max_trans_err, 0.05);
	EXPECT_LT(st.max_rot_err_deg, 0.1);
}

TEST(Drive, Vlp16Urban)
{
	LidarModel m = vlp16();
	m.noise_sigma = 0.01;
	const DriveStats st = drive(m, vlp16Options(), curvyPath(), 1.0, 40, 11, std::getenv("VLO_VERBOSE") != nullptr);
	std::printf("VLP-16: %.0f m, final err %.3f m (%.2f%%), max err %.3f m, max rot err %.3f deg, %.1f ms/frame (max %.1f)\n",
		st.length, st.final_trans_err, 100 * st.final_trans_err / st.length, st.max_trans_err, st.max_rot_err_deg,
		st.mean_ms, st.max_ms);
	EXPECT_EQ(st.not_ok, 0);
	EXPECT_LT(st.max_trans_err, 0.1);
	EXPECT_LT(st.max_rot_err_deg, 0.2);
}

TEST(Drive, DeskewUndoesTheMotionDuringTheSweep)
{
	// 15 m/s through the bends: without deskewing, each sweep is smeared by 1.5 m and 3 deg.
	LidarModel m = vlp16();
	m.noise_sigma = 0.01;
	LoamOptions o = vlp16Options();
	const DriveStats raw = drive(m, o, curvyPath(), 1.5, 30, 13, false, true);
	o.scan.deskew = true;
	o.scan.deskew_reference = 1.0;
	const DriveStats fixed = drive(m, o, curvyPath(), 1.5, 30, 13, std::getenv("VLO_VERBOSE") != nullptr, true);
	std::printf("moving sweeps over %.0f m: max error %.3f m / %.3f deg raw, %.3f m / %.3f deg deskewed\n", raw.length,
		raw.max_trans_err, raw.max_rot_err_deg, fixed.max_trans_err, fixed.max_rot_err_deg);
	EXPECT_LT(fixed.max_trans_err, 0.5 * raw.max_trans_err);
	EXPECT_LT(fixed.max_trans_err, 0.2);
	EXPECT_LT(fixed.max_rot_err_deg, 0.5 * raw.max_rot_err_deg);
}
}  // namespace vlo::loam::test
