// Moving traffic: vehicles keep to the road at their own speed, never overlap the ego vehicle or one
// another, come from both directions, overtake, are the same for the same seed; the LiDAR sees each at
// its firing's own time and the camera at the image time (against the vehicles' boxes, and between
// the sensors).
#include <gtest/gtest.h>
#include <vlo/sim/camera_sim.h>
#include <vlo/sim/drive.h>
#include <vlo/sim/rng.h>
#include <vlo/sim/simulator.h>
#include <vlo/sim/traffic.h>

#include <array>
#include <cmath>
#include <set>

using namespace vlo;
using namespace vlo::sim;

namespace
{
constexpr double kDuration = 40;

struct Scene
{
	Road road;
	VehicleMotion ego;
	Traffic traffic;
};

std::unique_ptr<Scene> makeScene(uint64_t seed, int vehicles)
{
	auto sc = std::make_unique<Scene>();
	Rng rng = Rng::stream(seed, "road");
	sc->road = generateRoad(RoadStyle{}, 120 + 600 + 180, rng);
	sc->ego = driveAlong(sc->road, DriveStyle{}, 120, kDuration, seed);
	sc->traffic = Traffic(sc->road, sc->ego, kDuration, vehicles, seed);
	return sc;
}

/// Whether two vehicle footprints (length x width, poses in the world) overlap, tested as
/// separating axes of the two rectangles.
bool overlap(const Eigen::Isometry3d& a, double la, double wa, const Eigen::Isometry3d& b, double lb, double wb)
{
	const Eigen::Vector2d d = (b.translation() - a.translation()).head<2>();
	const Eigen::Vector2d ax[4] = {a.linear().col(0).head<2>().normalized(), a.linear().col(1).head<2>().normalized(),
		b.linear().col(0).head<2>().normalized(), b.linear().col(1).head<2>().normalized()};
	for (const auto& n : ax)
	{
		const double ra = la / 2 * std::abs(ax[0].dot(n)) + wa / 2 * std::abs(ax[1].dot(n));
		const double rb = lb / 2 * std::abs(ax[2].dot(n)) + wb / 2 * std::abs(ax[3].dot(n));
		if (std::abs(d.dot(n)) > ra + rb) return false;
	}
	return true;
}
}  // namespace

TEST(Traffic, VehiclesKeepToTheRoadAtTheirSpeedAndNeverTouch)
{
	const auto sc = makeScene(3, 40);
	const Traffic& tr = sc->traffic;
	ASSERT_EQ(tr.vehicles().size(), 40u);
	int oncoming = 0, large = 0, overtakers = 0, samples = 0;
	for (std::size_t i = 0; i < tr.vehicles().size(); ++i)
	{
		const Vehicle& v = tr.vehicles()[i];
		oncoming += v.direction < 0;
		large += v.kind != VehicleKind::Car;
		bool behind = false, passed = false;
		for (double t = 0; t + 0.1 <= kDuration; t += 0.25)
		{
			if (!tr.present(i, t) || !tr.present(i, t + 0.1)) continue;
			++samples;
			const Eigen::Isometry3d p = tr.pose(i, t), q = tr.pose(i, t + 0.1);
			// On the asphalt of the narrowest road (trees: 3.6 m either side of the centre line), on its surface.
			const Station* st = sc->road.nearest(p.translation().head<2>(), 10);
			ASSERT_NE(st, nullptr) << "vehicle " << i << " left the road at t = " << t;
			const Eigen::Vector3d left(-std::sin(st->heading), std::cos(st->heading), 0);
			const double lat = left.dot(p.translation() - st->p);
			EXPECT_LE(std::abs(lat) + v.width / 2, 3.6) << "vehicle " << i << " t " << t;
			const Eigen::Vector2d along(std::cos(st->heading), std::sin(st->heading));
			const double ahead = (p.translation() - st->p).head<2>().dot(along);
			EXPECT_NEAR(p.translation().z(), sc->road.at(st->s).p.z() + st->grade * ahead, 0.05);
			// Its own speed, in its own direction (forward along its x axis).
			const Eigen::Vector3d step = q.translation() - p.translation();
			EXPECT_NEAR(step.norm() / 0.1, v.speed, 0.08 * v.speed) << "vehicle " << i << " t " << t;
			EXPECT_GT(step.dot(p.linear().col(0)), 0.99 * step.norm());
			// Never inside the ego vehicle (4.5 x 1.8 m about its centre, 1.4 m ahead of the rear axle).
			Eigen::Isometry3d ego = sc->ego.pose(t);
			ego.translate(Eigen::Vector3d(1.4, 0, 0));
			EXPECT_FALSE(overlap(ego, 4.5, 1.8, p, v.length, v.width)) << "vehicle " << i << " hits the ego at t " << t;
			const Eigen::Vector3d rel = ego.inverse() * p.translation();
			behind |= v.direction > 0 && rel.x() < -10;
			passed |= behind && rel.x() > 10;
			for (std::size_t j = i + 1; j < tr.vehicles().size(); ++j)
			{
				if (!tr.present(j, t)) continue;
				EXPECT_FALSE(overlap(p, v.length, v.width, tr.pose(j, t), tr.vehicles()[j].length, tr.vehicles()[j].width))
					<< "vehicles " << i << " and " << j << " at t " << t;
			}
		}
		overtakers += passed;
	}
	EXPECT_GT(samples, 1000);
	EXPECT_EQ(oncoming, 20);
	EXPECT_GE(large, 3);  // vans and trucks
	EXPECT_GE(overtakers, 5) << "same-direction vehicles that came from behind and passed the ego vehicle";
}

TEST(Traffic, SameSeedSameTrafficOtherSeedOther)
{
	const auto a = makeScene(5, 12), b = makeScene(5, 12), c = makeScene(6, 12);
	for (std::size_t i = 0; i < 12; ++i)
	{
		EXPECT_EQ(a->traffic.vehicles()[i].s0, b->traffic.vehicles()[i].s0);
		EXPECT_EQ(a->traffic.vehicles()[i].speed, b->traffic.vehicles()[i].speed);
		EXPECT_TRUE(a->traffic.pose(i, 7.3).isApprox(b->traffic.pose(i, 7.3)));
	}
	EXPECT_NE(a->traffic.vehicles()[0].speed, c->traffic.vehicles()[0].speed);
	EXPECT_TRUE(makeScene(5, 0)->traffic.vehicles().empty());
}

TEST(Traffic, LidarSeesEachVehicleAtItsFiringTimeAndTheCameraAtTheImageTime)
{
	SimConfig cfg;
	cfg.frames = 200, cfg.seed = 8, cfg.traffic = 40, cfg.lidar_distortion = true;
	cfg.range_noise = cfg.image_noise = cfg.dropout = 0;
	Simulator sim(cfg);
	const Traffic& tr = sim.traffic();
	// The frame with the most vehicles in front of the camera within 40 m.
	int best = 0, most = -1;
	for (int k = 0; k < sim.frameCount(); k += 5)
	{
		int n = 0;
		for (std::size_t i = 0; i < tr.vehicles().size(); ++i)
		{
			if (!tr.present(i, sim.frameTime(k))) continue;
			const Eigen::Vector3d p = sim.vehiclePose(k).inverse() * tr.pose(i, sim.frameTime(k)).translation();
			n += p.x() > 6 && p.x() < 40 && std::abs(p.y()) < 0.4 * p.x();
		}
		if (n > most) most = n, best = k;
	}
	ASSERT_GE(most, 2);
	RenderedView depth;
	const Frame f = sim.frame(best, &depth);
	ASSERT_TRUE(f.scan.has_time);
	const double t = sim.frameTime(best);
	std::vector<std::size_t> all(tr.vehicles().size());
	for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
	const Eigen::Isometry3d CL = f.rig.camera_T_lidar();
	const PinholeCamera& K = f.rig.camera;
	std::size_t onVehicle = 0, atRange = 0, offThen = 0, inImage = 0, imageAgrees = 0;
	for (const auto& p : f.scan)
	{
		// Where the beam was at its firing time, and what it hits of the vehicles there and then.
		const Eigen::Isometry3d L = sim.vehiclePoseAt(t + p.time) * f.rig.vehicle_T_lidar;
		const Eigen::Vector3d pl(p.x, p.y, p.z), dir = L.linear() * pl.normalized();
		double r = 0;
		if (Traffic::raycast(tr.placed(all, t + p.time), L.translation(), dir, 120, r) < 0 || std::abs(r - pl.norm()) > 0.3) continue;
		++onVehicle;
		atRange += std::abs(r - pl.norm()) < 0.01;
		// The same beam against the vehicles at the frame's time: the moving ones were elsewhere.
		double r0 = 0;
		offThen += Traffic::raycast(tr.placed(all, t), L.translation(), dir, 120, r0) < 0 || std::abs(r0 - pl.norm()) > 0.05;
		// Fired within 4 ms of the image: the camera sees the same surface (vehicles move < 10 cm).
		const Eigen::Vector3d c = CL * pl;
		if (std::abs(p.time) > 0.004 || c.z() < 3) continue;
		const double u = K.fx * c.x() / c.z() + K.cx, v = K.fy * c.y() / c.z() + K.cy;
		if (u < 0 || v < 0 || u > K.width - 1 || v > K.height - 1) continue;
		++inImage;
		const float z = CameraSim::depthAt(depth, u, v);
		imageAgrees += z > 0 && std::abs(z - c.z()) < 0.1 + 0.005 * c.z();
	}
	EXPECT_GT(onVehicle, 500u);
	EXPECT_GE(atRange, 0.99 * onVehicle) << atRange << " of " << onVehicle;
	EXPECT_GT(offThen, 0.2 * onVehicle) << "points that only the vehicles at the firing time explain";
	EXPECT_GT(inImage, 100u);
	EXPECT_GE(imageAgrees, 0.9 * inImage) << imageAgrees << " of " << inImage;
}

// --traffic-without-returns: the vehicles block beams and return nothing (the floor for any removal of
// moving points): the scan is the one with returns less exactly its
// returns from vehicles (noise off: the same points), and no return lies behind a vehicle.
TEST(Traffic, WithoutReturnsTheVehiclesHideTheWorldAndShowNothing)
{
	auto config = [](bool returns) {
		SimConfig cfg;
		cfg.lidar = lidarByName("vlp16");
		cfg.frames = 200, cfg.seed = 8, cfg.traffic = 40, cfg.traffic_lidar_returns = returns;
		cfg.lidar_distortion = true;  // each point's firing time, to place the vehicles
		cfg.range_noise = cfg.image_noise = cfg.dropout = 0;
		return cfg;
	};
	int best = 0, most = -1;
	Frame h;
	{
		Simulator hidden(config(false));  // one simulator at a time
		for (int k = 0; k < hidden.frameCount(); k += 5)
			if (hidden.vehiclesWithin(k, 20) > most) most = hidden.vehiclesWithin(k, 20), best = k;
		h = hidden.frame(best);
	}
	ASSERT_GE(most, 2);
	Simulator seen(config(true));
	const Frame s = seen.frame(best);
	const Traffic& tr = seen.traffic();
	std::vector<std::size_t> all(tr.vehicles().size());
	for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
	// Range at which the beam through p meets a vehicle at p's firing time (infinity: none).
	auto vehicleRange = [&](const LidarPoint& p) {
		const double t = seen.frameTime(best) + p.time;
		const Eigen::Isometry3d L = seen.vehiclePoseAt(t) * h.rig.vehicle_T_lidar;
		const Eigen::Vector3d pl(p.x, p.y, p.z);
		double r = 0;
		return Traffic::raycast(tr.placed(all, t), L.translation(), L.linear() * pl.normalized(), 200, r) < 0 ? HUGE_VAL : r;
	};
	std::set<std::array<float, 3>> hiddenPoints;
	std::size_t behind = 0;
	for (const auto& p : h.scan)
	{
		hiddenPoints.insert({p.x, p.y, p.z});
		behind += vehicleRange(p) < std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z) - 0.01;
	}
	EXPECT_EQ(behind, 0u) << "returns from behind a vehicle";
	std::size_t onVehicles = 0, elsewhere = 0;
	for (const auto& p : s.scan)
	{
		const bool onVehicle = std::abs(vehicleRange(p) - std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z)) < 0.01;
		onVehicles += onVehicle;
		elsewhere += !onVehicle && hiddenPoints.count({p.x, p.y, p.z});
	}
	EXPECT_GT(onVehicles, 200u) << "vehicles within 20 m";
	EXPECT_EQ(elsewhere, h.scan.size()) << "every return without the vehicles' is one of the scan with them";
	EXPECT_EQ(s.scan.size(), h.scan.size() + onVehicles) << "and only the vehicles' returns are missing";
}
