#pragma once
// What to simulate: scenario, sensors and their placement, noise, length, seed.
#include <vlo/core/frame.h>
#include <vlo/sim/realism.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vlo::sim
{
enum class Scenario
{
	Urban,  ///< buildings, parked cars, poles, trees, walls along a road with bends and slopes
	Trees,  ///< a winding road with only trees and ground: few planes, hard for LOAM
	Corridor,  ///< urban, then a long straight between smooth textured walls, then urban again
	Loop,  ///< a 504 m city-block circuit driven lap after lap, turning around to drive it back (circuit.h)
	Facades,  ///< a straight street of identical units (facade, lamp, car, tree) every facade_period metres
	Avenue,  ///< a gentle road at 11-13 m/s between dense trees and bushes right beside it (a KITTI raw tree stretch)
	Residential  ///< 11-13 m/s past front yards (hedges, fences, bushes, driveways) and detached houses (KITTI raw 0013)
};
/// "urban" | "trees" | "corridor" | "loop" | "facades" | "avenue" | "residential"; InputError otherwise.
Scenario parseScenario(const std::string& name);
std::string scenarioName(Scenario s);

/// A spinning multi-beam LiDAR.
struct LidarModel
{
	std::string name;
	std::vector<double> elevations_deg;  ///< one per beam (ring), top to bottom
	int azimuth_steps = 2000;  ///< firings per revolution
	double min_range = 1.0, max_range = 100.0;  ///< m
	double period = 0.1;  ///< s per revolution
};
LidarModel hdl64();  ///< 64 beams +2 .. -24.8 deg, 0.17 deg azimuth (KITTI's sensor)
LidarModel vlp16();  ///< 16 beams +-15 deg, 0.2 deg azimuth
/// "hdl64" | "vlp16"; InputError otherwise.
LidarModel lidarByName(const std::string& name);

/// KITTI-like rig: camera 0 intrinsics (1241x376, f 718.856), camera 1.65 m and LiDAR 1.73 m above
/// the ground; the vehicle frame sits on the ground below the rear axle, so both extrinsics have a
/// lever arm and a small rotation.
SensorRig defaultRig();

/// Sets the camera's lens from "K1,K2,P1,P2[,K3]" (plumb_bob) or, with `fisheye`, "K1,K2,K3,K4"
/// (kannala_brandt = equidistant). InputError naming --camera-distortion on a malformed list.
void setLens(PinholeCamera& camera, const std::string& coefficients, bool fisheye);

struct SimConfig
{
	Scenario scenario = Scenario::Urban;
	LidarModel lidar = hdl64();
	SensorRig rig = defaultRig();
	int frames = 100;
	uint64_t seed = 1;
	double rate_hz = 10;  ///< camera and LiDAR frames per second
	bool lidar_distortion = false;  ///< each firing at its own time (see doc/SIMULATOR.md)
	/// With lidar_distortion: each return moved into the LiDAR frame at the frame's time exactly (time
	/// written as 0): the rolling sweep's sampling without its distortion, what an ideal deskew gives.
	bool lidar_ideal_deskew = false;
	/// false: the sweep is written without per-point times and rings, as KITTI raw's and most recordings'
	/// (a raw sweep: its motion distortion, if any, stays in the points with nothing to undo it by).
	bool lidar_point_times = true;
	/// A real sensor's errors (realism.h); off here (the exact sensor the unit tests need), on in vlo-sim
	/// unless --no-realism. When on, they replace range_noise, dropout and image_noise.
	SensorRealism realism;
	double range_noise = 0.02;  ///< m, 1 sigma
	double image_noise = 2.0;  ///< gray levels, 1 sigma
	double dropout = 0.005;  ///< probability that a return is lost
	/// Mean depth (m) at which a LiDAR beam that enters a tree crown or bush returns from a leaf (see
	/// foliage.h); 0 = crowns are solid hulls for the LiDAR as for the camera.
	double foliage_depth = 0;
	/// Frames [blackout_first, blackout_end) get a uniform grey image: a blinded camera (glare, a tunnel
	/// exit), to exercise the VO's LOST state and the LiDAR-only fallback.
	int blackout_first = -1, blackout_end = -1;
	/// Vehicles driving the road in both directions, seen by both sensors (traffic.h); 0 = a static world.
	int traffic = 0;
	/// false: the vehicles block the LiDAR's beams but return nothing, as if every moving point had been
	/// removed perfectly (what rejecting moving points can at best reach); the camera still sees them.
	bool traffic_lidar_returns = true;
	/// KITTI camera-0 poses to drive along instead of a generated drive ("" = generate).
	std::string kitti_poses;
	/// Loop: the vehicle turns around at the turning place nearest to this many laps, then drives the
	/// circuit the other way; 0 = never.
	double reverse_after_laps = 1.5;
	/// Facades: metres between the street's identical units (a multiple of 8 m, so the ground repeats too).
	double facade_period = 24;
	/// Strong sun: the crowns cast hard, dappled shadows on everything the camera sees (sun_shadows.h).
	bool sun_shadows = false;
};
}  // namespace vlo::sim
