// The revisit scenarios: the city-block circuit (closed, driven lap after lap and back the other way,
// the same scenery at every revisit) and the street of identical facades (the same unit every P m).
#include <gtest/gtest.h>
#include <vlo/core/error.h>
#include <vlo/sim/circuit.h>
#include <vlo/sim/scenarios.h>
#include <vlo/sim/simulator.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdlib>
#include <string>
#include <unordered_set>

using namespace vlo;
using namespace vlo::sim;

namespace
{
SimConfig exact(Scenario sc, int frames)
{
	SimConfig c;
	c.scenario = sc, c.frames = frames, c.seed = 3;
	c.range_noise = c.image_noise = c.dropout = 0;
	return c;
}

double yaw(const Eigen::Isometry3d& T) { return std::atan2(T.linear()(1, 0), T.linear()(0, 0)); }
double angleBetween(double a, double b) { return std::abs(std::atan2(std::sin(a - b), std::cos(a - b))); }

/// The frame nearest to world point xy among frames [from, to).
int nearestFrame(const Simulator& sim, const Eigen::Vector2d& xy, int from, int to)
{
	int best = from;
	for (int k = from; k < to; ++k)
		if ((sim.vehiclePose(k).translation().head<2>() - xy).norm() < (sim.vehiclePose(best).translation().head<2>() - xy).norm())
			best = k;
	return best;
}

/// Distance driven (m) from frame 0 to each frame.
std::vector<double> odometer(const Simulator& sim)
{
	std::vector<double> d{0};
	for (int k = 1; k < sim.frameCount(); ++k)
		d.push_back(d.back() + (sim.vehiclePose(k).translation() - sim.vehiclePose(k - 1).translation()).norm());
	return d;
}

/// Points of frame k's scan in the world within `range` of the sensor, higher than `above` (world z):
/// above the ground, which the rings sample at other places from another viewpoint.
std::vector<Eigen::Vector3d> worldPoints(Simulator& sim, int k, double range, double above)
{
	const Frame f = sim.frame(k);
	const Eigen::Isometry3d L = sim.vehiclePose(k) * f.rig.vehicle_T_lidar;
	std::vector<Eigen::Vector3d> out;
	for (const auto& p : f.scan)
	{
		const Eigen::Vector3d w = L * Eigen::Vector3d(p.x, p.y, p.z);
		if (Eigen::Vector3d(p.x, p.y, p.z).norm() < range && w.z() > above) out.push_back(w);
	}
	return out;
}

/// Share of `b` within ~`cell` of a point of `a` (a voxel hash with the neighbouring cells).
double overlap(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b, double cell)
{
	auto key = [&](const Eigen::Vector3i& v) { return (int64_t(v.x()) * 73856093) ^ (int64_t(v.y()) * 19349663) ^ (int64_t(v.z()) * 83492791); };
	auto voxel = [&](const Eigen::Vector3d& p) { return Eigen::Vector3i((p / cell).array().floor().cast<int>()); };
	std::unordered_set<int64_t> cells;
	for (const auto& p : a) cells.insert(key(voxel(p)));
	std::size_t near = 0;
	for (const auto& p : b)
	{
		const Eigen::Vector3i v = voxel(p);
		bool found = false;
		for (int dx = -1; dx <= 1 && !found; ++dx)
			for (int dy = -1; dy <= 1 && !found; ++dy)
				for (int dz = -1; dz <= 1 && !found; ++dz) found = cells.count(key(v + Eigen::Vector3i(dx, dy, dz))) > 0;
		near += found;
	}
	return b.empty() ? 0 : double(near) / b.size();
}
}  // namespace

TEST(Circuit, IsClosedWithTightCornersAndStraightTurningPlaces)
{
	const Circuit c = cityBlockCircuit();
	const Road& r = c.road;
	ASSERT_TRUE(r.closed());
	EXPECT_NEAR(r.length(), 515, 25);
	const auto& st = r.stations();
	// The lap ends where it starts, without a jump: every step is the station spacing.
	EXPECT_LT((st.back().p - st.front().p).norm(), 0.01);
	EXPECT_LT(angleBetween(st.back().heading, st.front().heading), 1e-6);
	double path = 0, kmax = 0;
	for (std::size_t i = 1; i < st.size(); ++i)
	{
		const double step = (st[i].p - st[i - 1].p).head<2>().norm();
		EXPECT_NEAR(step, 0.5, 0.5 * 0.03) << "at " << st[i].s;
		path += step;
		kmax = std::max(kmax, std::abs(st[i].curvature));
	}
	EXPECT_NEAR(path, r.length(), 0.5);
	EXPECT_NEAR(1 / kmax, 12.6, 0.1);  // the tightest corner
	// Arc lengths wrap around the lap; the seam is no "other part of the road".
	EXPECT_LT((r.at(r.length() + 10).p - r.at(10).p).norm(), 1e-9);
	EXPECT_LT((r.at(-10).p - r.at(r.length() - 10).p).norm(), 1e-9);
	EXPECT_EQ(r.nearest(st.front().p.head<2>(), 5, 0, 30), nullptr);
	ASSERT_EQ(c.turning_places.size(), 2u);
	for (double t : c.turning_places)
		for (double ds = -20; ds <= 8; ds += 1) EXPECT_LT(std::abs(r.at(t + ds).curvature), 1e-9) << t << " " << ds;
	EXPECT_NEAR(turnaroundDistance(c, 1.5), c.turning_places[1] + r.length(), 1e-9);
	EXPECT_NEAR(turnaroundDistance(c, 1.0), r.length(), 1e-9);
	EXPECT_EQ(turnaroundDistance(c, 0), 0);
}

TEST(LoopDrive, ComesBackToTheStartEachLapThenDrivesTheOtherWay)
{
	SimConfig cfg = exact(Scenario::Loop, 1500);
	Simulator sim(cfg);
	const double L = sim.road().length();
	const std::vector<double> d = odometer(sim);
	const Eigen::Vector2d start = sim.vehiclePose(0).translation().head<2>();
	const double yaw0 = yaw(sim.vehiclePose(0));
	// The lap ends within a frame's travel of the start, heading the same way, one lap further on.
	int from = 0;
	while (d[from] < 0.5 * L) ++from;
	const int lap = nearestFrame(sim, start, from, sim.frameCount());
	EXPECT_LT((sim.vehiclePose(lap).translation().head<2>() - start).norm(), 1.0);
	EXPECT_LT(angleBetween(yaw(sim.vehiclePose(lap)), yaw0), 0.05);
	EXPECT_NEAR(d[lap], L + 2 * M_PI * 1.75, 3);  // the right lane is on the outside
	ASSERT_GT(d.back(), 2.1 * L) << "the drive is too short for the test";
	// After the U-turn (1.5 laps) the vehicle passes the start again in the other lane, the other way.
	while (d[from] < 1.75 * L) ++from;
	const int back = nearestFrame(sim, start, from, sim.frameCount());
	EXPECT_NEAR((sim.vehiclePose(back).translation().head<2>() - start).norm(), 3.5, 0.6);
	EXPECT_GT(angleBetween(yaw(sim.vehiclePose(back)), yaw0), M_PI - 0.1);
	// Speeds as in the urban drive, slower in the corners: lateral acceleration v^2 k within limits.
	double amax = 0, vmax = 0;
	for (int k = 1; k + 1 < sim.frameCount(); ++k)
	{
		const Eigen::Vector3d a = sim.vehiclePose(k - 1).translation(), b = sim.vehiclePose(k).translation(),
							  c = sim.vehiclePose(k + 1).translation();
		const Eigen::Vector3d v = (c - a) * 5, acc = (c - 2 * b + a) * 100;
		vmax = std::max(vmax, v.norm());
		amax = std::max(amax, (acc - acc.dot(v.normalized()) * v.normalized()).norm());
	}
	EXPECT_LT(vmax, 14.5);
	EXPECT_LT(amax, 3.5);
}

TEST(LoopDrive, RevisitsSeeTheSameScenery)
{
	Simulator sim(exact(Scenario::Loop, 1400));
	const std::vector<double> d = odometer(sim);
	const double L = sim.road().length();
	const Eigen::Vector2d start = sim.vehiclePose(0).translation().head<2>();
	int from = 0;
	while (d[from] < 0.5 * L) ++from;
	const int away = from;  // half a lap on: other scenery
	const int lap = nearestFrame(sim, start, from, sim.frameCount());
	while (d[from] < 1.75 * L) ++from;
	const int back = nearestFrame(sim, start, from, sim.frameCount());  // after the U-turn, the other way
	// Upright surfaces within 30 m of frame 0, seen again after a lap and on the way back.
	const double ground = sim.vehiclePose(0).translation().z() + 0.5;
	const auto first = worldPoints(sim, 0, 30, ground);
	const double same = overlap(first, worldPoints(sim, lap, 30, ground), 0.1);
	const double reverse = overlap(first, worldPoints(sim, back, 30, ground), 0.1);
	const double other = overlap(first, worldPoints(sim, away, 30, ground), 0.1);
	EXPECT_GT(same, 0.95);
	EXPECT_GT(reverse, 0.85);
	EXPECT_LT(other, 0.05);
}

TEST(KittiPath, RevisitSeesTheSameScenery)
{
	// KITTI 00 drives again along frames 113-205 at frames 1559-1641 (its truth 0.75 m lower there): the
	// world, built once along the whole path, is the same. Upright surfaces above the first visit's ground.
	const std::string dir = testing::TempDir() + "vlo_sim_revisit";
	const std::string unpack = "mkdir -p '" + dir + "' && tar -xJf '" VLO_SHARED_DATA "/kitti_gt_poses.tar.xz' -C '" + dir + "' kitti_gt_poses/00.txt";
	ASSERT_EQ(std::system(unpack.c_str()), 0);
	SimConfig cfg = exact(Scenario::Urban, 1650);
	cfg.kitti_poses = dir + "/kitti_gt_poses/00.txt";
	Simulator sim(cfg);
	const int first = 156, again = nearestFrame(sim, sim.vehiclePose(first).translation().head<2>(), 1500, 1650);
	EXPECT_NEAR(again, 1600, 3);
	const double ground = sim.vehiclePose(first).translation().z() + 0.5;
	const auto seen = worldPoints(sim, first, 30, ground);
	const double same = overlap(seen, worldPoints(sim, again, 30, ground), 0.1);
	const double other = overlap(seen, worldPoints(sim, 1000, 30, ground), 0.1);
	EXPECT_GT(same, 0.95);
	EXPECT_LT(other, 0.05);
}

/// Ranges of rays cast from (x, 0, 1.7) over the whole sphere but straight up and down.
std::vector<double> rangesFrom(const World& w, double x)
{
	std::vector<double> out;
	for (double el : {-0.3, -0.1, 0.0, 0.15, 0.5})
		for (int i = 0; i < 72; ++i)
		{
			const double az = 2 * M_PI * i / 72;
			const Eigen::Vector3d dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
			double r = 60;
			w.raycast(Eigen::Vector3d(x, 0, 1.7), dir, 60, r);
			out.push_back(r);
		}
	return out;
}

/// Share of the rays whose ranges differ by more than 1 mm.
double differing(const std::vector<double>& a, const std::vector<double>& b)
{
	std::size_t n = 0;
	for (std::size_t i = 0; i < a.size(); ++i) n += std::abs(a[i] - b[i]) > 1e-3;
	return double(n) / a.size();
}

TEST(Facades, TheStreetRepeatsEveryPeriod)
{
	const Road road = straightRoad(500);
	for (double period : {24.0, 32.0})
	{
		WorldSpec spec;
		spec.scenario = Scenario::Facades, spec.seed = 3, spec.facade_period = period;
		const World w = buildWorld(spec, road);
		const double x0 = 5 * period + 3;
		const std::vector<double> here = rangesFrom(w, x0);
		std::size_t hits = 0;
		for (double r : here) hits += r < 59;
		EXPECT_GT(hits, here.size() / 2);
		// The same world seen from one, two and three periods further on...
		for (int k = 1; k <= 3; ++k)
		{
			const std::vector<double> there = rangesFrom(w, x0 + k * period);
			double worst = 0;
			for (std::size_t i = 0; i < here.size(); ++i) worst = std::max(worst, std::abs(here[i] - there[i]));
			EXPECT_LT(worst, 1e-4) << "period " << period << ", " << k << " periods on";
		}
		// ... but not from half a period on, nor with another period.
		EXPECT_GT(differing(here, rangesFrom(w, x0 + period / 2)), 0.3) << period;
		EXPECT_GT(differing(here, rangesFrom(w, x0 + (period == 24 ? 32 : 24))), 0.15) << period;
	}
}

TEST(Facades, TheDriveGoesStraightOnWithoutRevisit)
{
	Simulator sim(exact(Scenario::Facades, 200));
	for (int k = 1; k < sim.frameCount(); ++k)
	{
		const Eigen::Vector3d a = sim.vehiclePose(k - 1).translation(), b = sim.vehiclePose(k).translation();
		EXPECT_GT(b.x() - a.x(), 0.3) << k;
		EXPECT_LT(std::abs(b.y() + 1.75), 0.3) << k;
	}
	EXPECT_GT(sim.vehiclePose(199).translation().x() - sim.vehiclePose(0).translation().x(), 150);
}

TEST(RevisitScenarios, RefuseWhatTheyCannotDo)
{
	SimConfig cfg = exact(Scenario::Facades, 2);
	cfg.facade_period = 20;
	EXPECT_THROW(Simulator{cfg}, InputError);
	cfg = exact(Scenario::Loop, 2);
	cfg.traffic = 3;
	EXPECT_THROW(Simulator{cfg}, InputError);
	cfg.traffic = 0, cfg.kitti_poses = "poses.txt";
	EXPECT_THROW(Simulator{cfg}, InputError);
	cfg.kitti_poses.clear(), cfg.reverse_after_laps = -1;
	EXPECT_THROW(Simulator{cfg}, InputError);
}
