#include "traffic_mesh.h"

#include <vlo/core/error.h>
#include <vlo/sim/camera_errors.h>
#include <vlo/sim/camera_sim.h>
#include <vlo/sim/circuit.h>
#include <vlo/sim/lidar_errors.h>
#include <vlo/sim/lidar_sim.h>
#include <vlo/sim/renderer.h>
#include <vlo/sim/rng.h>
#include <vlo/sim/scenarios.h>
#include <vlo/sim/simulator.h>
#include <vlo/sim/sun_shadows.h>

#include <mrpt/opengl/COpenGLScene.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

namespace vlo::sim
{
namespace
{
constexpr double kBehind = 120;  // road before the start (the LiDAR sees 100 m back)
constexpr double kAhead = 180;  // road after the end (the camera sees up to 160 m)

RoadStyle styleFor(Scenario sc)
{
	RoadStyle st;
	if (sc == Scenario::Trees)
		st.max_curvature = 1 / 45.0, st.min_curvature = 1 / 300.0, st.straight_fraction = 0.15, st.grade_amplitude = 0.05;
	return st;
}

/// KITTI camera-0 poses -> vehicle poses in a world whose origin is the vehicle at frame 0.
Trajectory vehicleFromKitti(const std::string& path, int frames, double rate, const SensorRig& rig)
{
	const Trajectory cam = io::readKittiPoses(path);
	if (static_cast<int>(cam.size()) < frames)
		failInput(path, "has " + std::to_string(cam.size()) + " poses, fewer than --frames " + std::to_string(frames));
	const Eigen::Isometry3d VC = rig.vehicle_T_camera, C0inv = cam.front().pose.inverse();
	Trajectory out;
	for (int k = 0; k < frames; ++k) out.push_back({k / rate, VC * C0inv * cam[k].pose * VC.inverse()});
	return out;
}

/// The road and how the vehicle moves along it.
struct Drive
{
	Road road;
	VehicleMotion motion;
	double corridor_from = 0, corridor_to = 0;  ///< arc lengths of the corridor's walls
	Circuit circuit;  ///< loop: the circuit (its road is `road`) and where the vehicle turns around
	double turn_at = 0;
};

/// Road and motion along KITTI camera-0 poses.
Drive kittiDrive(const SimConfig& cfg)
{
	Drive d;
	if (cfg.scenario == Scenario::Corridor)
		failInput("--scenario corridor", "needs a generated drive (its long straight), not --trajectory");
	Trajectory v = vehicleFromKitti(cfg.kitti_poses, cfg.frames, cfg.rate_hz, cfg.rig);
	// The road's centre line runs 1.75 m to the left of the vehicle (it drives in the right lane).
	std::vector<Eigen::Vector3d> centre;
	for (const auto& p : v) centre.push_back(p.pose * Eigen::Vector3d(0, -kLaneOffset, 0));
	d.road = roadThrough(centre, kAhead);
	if (v.size() == 1) v.push_back({v[0].t + 1 / cfg.rate_hz, v[0].pose});  // a parked vehicle
	d.motion = VehicleMotion(std::move(v));
	return d;
}

double driveDuration(const SimConfig& cfg) { return (cfg.frames - 1) / cfg.rate_hz + 0.2; }

/// Laps of the city-block circuit, turning around after cfg.reverse_after_laps.
Drive loopDrive(const SimConfig& cfg)
{
	Drive d;
	d.circuit = cityBlockCircuit();
	const double duration = driveDuration(cfg);
	DriveStyle ds;
	ds.lane_offset = 0;  // the lap path is the lane already
	ds.brake_for_bends = true;  // corners of 13 m radius and U-turns
	// The planned distance ignores the bends, so the path is long enough; 150 m more for the look ahead.
	const double dist = plannedDistance(ds, duration, cfg.seed) + 150;
	d.turn_at = turnaroundDistance(d.circuit, cfg.reverse_after_laps);
	d.motion = driveAlong(lapPath(d.circuit, dist, d.turn_at), ds, 0, duration, cfg.seed);
	d.road = d.circuit.road;
	return d;
}

/// A straight street whose start lies kBehind before the vehicle's.
Drive facadesDrive(const SimConfig& cfg)
{
	Drive d;
	const double duration = driveDuration(cfg);
	const DriveStyle ds;
	d.road = straightRoad(kBehind + plannedDistance(ds, duration, cfg.seed) + kAhead);
	d.motion = driveAlong(d.road, ds, kBehind, duration, cfg.seed);
	return d;
}

/// Random road and drive; the road is sized for the planned distance.
Drive generatedDrive(const SimConfig& cfg)
{
	Drive d;
	const double duration = driveDuration(cfg);
	DriveStyle ds;
	if (cfg.scenario == Scenario::Corridor) ds.v_min = 8, ds.v_max = 12;
	if (cfg.scenario == Scenario::Trees) ds.v_min = 7;
	if (cfg.scenario == Scenario::Avenue || cfg.scenario == Scenario::Residential)
		ds.v_min = 11, ds.v_max = 13;  // KITTI raw 2011_09_26_0013's speeds
	const double dist = plannedDistance(ds, duration, cfg.seed);
	RoadStyle st = styleFor(cfg.scenario);
	if (cfg.scenario == Scenario::Corridor)
	{
		// Entered after a quarter of the drive; left after three quarters, but never shorter than
		// 150 m so that even a short drive is degenerate for LiDAR inside it.
		d.corridor_from = kBehind + 0.25 * dist, d.corridor_to = kBehind + std::max(0.75 * dist, 0.25 * dist + 150);
		st.straight_from = d.corridor_from - 15, st.straight_to = d.corridor_to + 15;
	}
	Rng rng = Rng::stream(cfg.seed, "road");
	d.road = generateRoad(st, kBehind + dist + kAhead, rng);
	d.motion = driveAlong(d.road, ds, kBehind, duration, cfg.seed);
	return d;
}
}  // namespace

struct Simulator::Impl
{
	SimConfig cfg;
	Drive drive;
	World world;
	mrpt::opengl::COpenGLScene scene;
	std::unique_ptr<CameraSim> camera;
	std::unique_ptr<LidarSim> lidar;
	std::unique_ptr<LidarErrors> lidarErrors;  // the realistic unit's (null: the exact sensor)
	std::unique_ptr<Renderer> renderer;
	Traffic traffic;
	std::unique_ptr<TrafficMesh> trafficMesh;  // the camera's view of the traffic (null without traffic)
};

Simulator::Simulator(const SimConfig& cfg) : impl_(std::make_unique<Impl>())
{
	auto& d = *impl_;
	d.cfg = cfg;
	if (cfg.frames < 1) failInput("--frames", "must be at least 1");
	const bool ownRoad = cfg.scenario == Scenario::Loop || cfg.scenario == Scenario::Facades;
	if (ownRoad && !cfg.kitti_poses.empty())
		failInput("--scenario " + scenarioName(cfg.scenario), "has its own road: not with --trajectory");
	if (cfg.scenario == Scenario::Loop && cfg.traffic > 0)
		failInput("--traffic", "not on the loop (its vehicles drive one way along an open road)");
	if (cfg.scenario == Scenario::Facades && !(cfg.facade_period >= 16 && cfg.facade_period <= 96 && std::fmod(cfg.facade_period, 8) == 0))
		failInput("--facade-period", "must be a multiple of 8 m between 16 and 96");
	if (cfg.scenario == Scenario::Loop && !(cfg.reverse_after_laps >= 0 && cfg.reverse_after_laps <= 1000))
		failInput("--reverse-after", "must be between 0 (never) and 1000 laps");
	if (cfg.scenario == Scenario::Loop)
		d.drive = loopDrive(cfg);
	else if (cfg.scenario == Scenario::Facades)
		d.drive = facadesDrive(cfg);
	else
		d.drive = cfg.kitti_poses.empty() ? generatedDrive(cfg) : kittiDrive(cfg);
	WorldSpec spec;
	spec.scenario = cfg.scenario, spec.seed = cfg.seed;
	spec.corridor_from = d.drive.corridor_from, spec.corridor_to = d.drive.corridor_to;
	spec.turning_places = d.drive.circuit.turning_places;
	spec.park_from = d.drive.circuit.park_from, spec.park_to = d.drive.circuit.park_to;
	spec.facade_period = cfg.facade_period;
	d.world = buildWorld(spec, d.drive.road);

	d.scene.insert(d.world.makeOpenGL());
	if (cfg.traffic < 0) failInput("--traffic", "must not be negative");
	if (cfg.traffic > 0)
	{
		d.traffic = Traffic(d.drive.road, d.drive.motion, (cfg.frames - 1) / cfg.rate_hz, cfg.traffic, cfg.seed);
		d.trafficMesh = std::make_unique<TrafficMesh>(cfg.seed);
		d.scene.insert(d.trafficMesh->object());
	}
	auto vp = d.scene.getViewport("main");
	vp->setCustomBackgroundColor(mrpt::img::TColorf(0.80f, 0.82f, 0.86f, 1.0f));  // overcast sky

	d.camera = std::make_unique<CameraSim>(cfg.rig.camera);
	d.lidar = std::make_unique<LidarSim>(cfg.lidar, cfg.lidar_distortion, cfg.lidar_ideal_deskew);
	if (cfg.realism.enabled)
		d.lidarErrors = std::make_unique<LidarErrors>(cfg.realism.lidar, static_cast<int>(cfg.lidar.elevations_deg.size()), cfg.seed);
	std::vector<std::pair<int, int>> tiles{d.camera->tileSize()};
	for (int i = 0; i < d.lidar->viewCount(); ++i) tiles.push_back(d.lidar->tileSize());
	d.renderer = std::make_unique<Renderer>(tiles);
}

Simulator::~Simulator() = default;
const SimConfig& Simulator::config() const { return impl_->cfg; }
int Simulator::frameCount() const { return impl_->cfg.frames; }
double Simulator::frameTime(int k) const { return k / impl_->cfg.rate_hz; }
Eigen::Isometry3d Simulator::vehiclePoseAt(double t) const { return impl_->drive.motion.pose(t); }
Eigen::Isometry3d Simulator::vehiclePose(int k) const { return vehiclePoseAt(frameTime(k)); }
const World& Simulator::world() const { return impl_->world; }
const Road& Simulator::road() const { return impl_->drive.road; }
const Traffic& Simulator::traffic() const { return impl_->traffic; }

int Simulator::vehiclesWithin(int k, double radius) const
{
	return impl_->traffic.countWithin(vehiclePose(k).translation(), radius, frameTime(k));
}

Trajectory Simulator::groundTruth() const
{
	Trajectory gt;
	for (int k = 0; k < frameCount(); ++k) gt.push_back({frameTime(k), vehiclePose(k)});
	return relativeToFirst(gt);
}

Frame Simulator::frame(int k, RenderedView* camera_depth)
{
	auto& d = *impl_;
	const double t = frameTime(k);
	const SensorRig& rig = d.cfg.rig;
	const LidarSim::PoseAt lidarAt = [&](double tau) { return Eigen::Isometry3d(d.drive.motion.pose(t + tau) * rig.vehicle_T_lidar); };
	std::vector<View> views{d.camera->view(d.drive.motion.pose(t) * rig.vehicle_T_camera)};
	for (const View& v : d.lidar->views(lidarAt)) views.push_back(v);
	std::vector<RenderedView> tiles;
	MovingObjects moving;
	std::vector<std::size_t> nearby;  // vehicles the LiDAR may reach during the sweep
	if (d.trafficMesh)
	{
		d.trafficMesh->update(d.traffic, t);  // the camera sees them at the image time
		nearby = d.traffic.near(lidarAt(0).translation(), d.cfg.lidar.max_range, t, d.cfg.lidar.period);
		moving.at = [&](double tau) { return d.traffic.placed(nearby, t + tau); };
		moving.gray = [&](int slot) { return d.trafficMesh->gray(slot); };
		moving.returns = d.cfg.traffic_lidar_returns;
	}
	d.renderer->render(d.scene, views, tiles, true, d.trafficMesh ? d.trafficMesh->object().get() : nullptr);

	Frame f;
	f.index = static_cast<std::size_t>(k);
	f.t = t;
	f.rig = rig;
	if (d.cfg.sun_shadows) applySunShadows(tiles[0], views[0], d.world.foliage(), SunLight());
	Rng imageNoise = Rng::stream(d.cfg.seed, "image noise", static_cast<uint64_t>(k));
	const CameraRealism* camera = d.cfg.realism.enabled ? &d.cfg.realism.camera : nullptr;
	f.image = d.camera->image(tiles[0], d.cfg.image_noise, imageNoise, camera, camera ? exposureGain(*camera, d.cfg.seed, k) : 1.0);
	if (k >= d.cfg.blackout_first && k < d.cfg.blackout_end) f.image.asCvMatRef().setTo(cv::Scalar::all(128));
	f.has_image = true;
	Rng lidarNoise = Rng::stream(d.cfg.seed, "lidar noise", static_cast<uint64_t>(k));
	const std::vector<RenderedView> lt(std::make_move_iterator(tiles.begin() + 1), std::make_move_iterator(tiles.end()));
	const std::vector<View> lv(views.begin() + 1, views.end());
	f.scan = d.lidar->sample(lt, lv, lidarAt, d.world.foliage(), {d.cfg.range_noise, d.cfg.dropout, d.cfg.foliage_depth, d.lidarErrors.get()},
		lidarNoise, d.trafficMesh ? &moving : nullptr);
	if (!d.cfg.lidar_point_times) dropPointTimes(f.scan);
	f.has_scan = true;
	if (camera_depth) *camera_depth = std::move(tiles[0]);
	return f;
}

std::string Simulator::summary() const
{
	const auto& d = *impl_;
	std::ostringstream s;
	s.precision(1);
	s << std::fixed << scenarioName(d.cfg.scenario) << " world: " << d.world.triangleCount() << " triangles along "
	  << d.drive.road.length() << " m of road; drive " << pathLength(groundTruth()) << " m in " << frameCount() << " frames";
	if (d.drive.corridor_to > d.drive.corridor_from) s << "; corridor " << d.drive.corridor_to - d.drive.corridor_from << " m";
	if (d.cfg.scenario == Scenario::Loop)
		s << "; circuit " << d.drive.road.length() << " m a lap"
		  << (d.drive.turn_at > 0 ? ", U-turn after " + std::to_string(std::lround(d.drive.turn_at)) + " m" : "");
	if (d.cfg.scenario == Scenario::Facades) s << "; identical facades every " << d.cfg.facade_period << " m";
	if (d.cfg.traffic > 0) s << "; traffic " << d.cfg.traffic << " vehicles";
	return s.str();
}
}  // namespace vlo::sim
