#pragma once
// Moving traffic on the road: cars, vans and trucks driving at constant speeds along the lanes, in the
// ego vehicle's direction (faster than it, so they overtake it, swinging towards the centre line while
// they pass) and oncoming. Their motion is a closed form of time, so each sensor sees them at its own
// instant: the camera at the image time, the LiDAR at each firing's time. Deterministic from the seed;
// ground truth stays the ego vehicle's alone.
#include <vlo/sim/drive.h>
#include <vlo/sim/road.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace vlo::sim
{
/// A box of a vehicle's body, in the vehicle frame (x forward, y left, z up, origin on the ground at
/// the centre of the footprint): centre of its footprint at (x, 0, z0), size sx x sy x sz.
struct VehiclePart
{
	double x = 0, z0 = 0, sx = 1, sy = 1, sz = 1;
	int side_tex = 0, top_tex = 0;  ///< indices into the traffic's texture set (see TrafficMesh)
};

enum class VehicleKind
{
	Car,
	Van,
	Truck
};

struct Vehicle
{
	VehicleKind kind = VehicleKind::Car;
	std::vector<VehiclePart> parts;
	double length = 4.5, width = 1.8;
	double s0 = 0;  ///< arc length at t = 0 (may lie off the road: it enters later)
	double speed = 10;  ///< m/s along the road
	int direction = 1;  ///< +1: the ego vehicle's direction, -1: oncoming
	int paint = 0;  ///< colour variant of its body textures
};

/// Texture slots of the vehicle parts (TrafficMesh creates them in this order).
namespace vehicle_tex
{
constexpr int kPaints = 3;
constexpr int bodySide(int paint) { return 2 * paint; }
constexpr int bodyTop(int paint) { return 2 * paint + 1; }
constexpr int kCabinSide = 2 * kPaints, kCargoSide = kCabinSide + 1, kCargoTop = kCabinSide + 2, kCount = kCabinSide + 3;
}  // namespace vehicle_tex

class Traffic
{
   public:
	Traffic() = default;
	/// `count` vehicles around the ego drive `ego` on `road` over [0, duration] s: about half of them
	/// oncoming, the others behind the ego vehicle and faster than its top speed.
	Traffic(const Road& road, const VehicleMotion& ego, double duration, int count, uint64_t seed);

	const std::vector<Vehicle>& vehicles() const { return vehicles_; }
	/// Arc length of vehicle i at time t (along the centre line).
	double arcLength(std::size_t i, double t) const;
	/// Whether vehicle i is on the road at time t (vehicles enter and leave at the road's ends).
	bool present(std::size_t i, double t) const;
	/// world_T_vehicle of vehicle i at time t (on the road surface, along its lane).
	Eigen::Isometry3d pose(std::size_t i, double t) const;
	/// Lateral offset of vehicle i from the centre line at time t (m, to the left).
	double lateral(std::size_t i, double t) const;

	/// Vehicles present around time t whose body may come within `radius` of p during [t - slack, t + slack].
	std::vector<std::size_t> near(const Eigen::Vector3d& p, double radius, double t, double slack) const;

	/// Vehicles present at time t within `radius` of p (their centres).
	int countWithin(const Eigen::Vector3d& p, double radius, double t) const;

	/// A vehicle frozen at one instant, ready for ray casts.
	struct Placed
	{
		const Vehicle* vehicle;
		Eigen::Isometry3d vehicle_T_world;
	};
	/// The `candidates` (indices) present at time t, where they are then.
	std::vector<Placed> placed(const std::vector<std::size_t>& candidates, double t) const;
	/// First hit of the ray o + r d (|d| = 1, r in (0, max_range]) with the placed vehicles. Returns the
	/// texture slot of the face hit (a part's top or side), or -1 for none.
	static int raycast(const std::vector<Placed>& placed, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
		double max_range, double& range);

   private:
	const Road* road_ = nullptr;
	std::vector<Vehicle> vehicles_;
	std::vector<double> egoS_;  // the ego vehicle's arc length every kStep s from t = -kPad
	double egoArcLength(double t) const;
};
}  // namespace vlo::sim
