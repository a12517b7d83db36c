#pragma once
// Analytic test worlds for the LOAM tests and benchmark: a flat ground, yaw-rotated boxes
// (buildings, cars, walls) and vertical cylinders (poles, trunks), scanned by an exact ray caster
// with the beam layout of a VLP-16 or an HDL-64E.
#include <vlo/core/frame.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

namespace vlo::loam::test
{
struct Box
{
	Eigen::Vector3d centre, half;  ///< half sizes along the box axes
	double yaw = 0;
};
struct Cylinder
{
	Eigen::Vector2d centre;
	double radius = 0.1, z0 = 0, z1 = 3;
};

class World
{
   public:
	bool ground = true;  ///< the plane z = 0
	std::vector<Box> boxes;
	std::vector<Cylinder> cylinders;

	/// Distance to the first surface along the unit ray o + t d (t < max_t), or max_t.
	double cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_t) const;
	/// The same, only over the objects listed (ground included when `ground`).
	double castSubset(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_t, const std::vector<int>& ids) const;
	std::size_t numObjects() const { return boxes.size() + cylinders.size(); }
};

struct LidarModel
{
	std::vector<double> elevations_deg;
	int columns = 1800;  ///< azimuth steps per revolution
	double max_range = 120.0;
	double noise_sigma = 0.0;  ///< range noise [m]
	bool nan_for_misses = false;  ///< emit NaN points where a beam hits nothing
	double period = 0.1;  ///< seconds per sweep (the points' times)
};
LidarModel vlp16();
LidarModel hdl64();  ///< the two-block layout, 2000 columns (~120k points)

/// One sweep in firing order (column by column, clockwise from azimuth 180 deg); points in the
/// LiDAR frame. The sensor moves from `start` to `end` (world poses) during the sweep, each column
/// measured at its own time; pass start == end for a still sensor. Every point gets its ring (rank
/// of its beam's elevation) and time (seconds from the end of the sweep, in [-period, 0)); the
/// scan's has_ring / has_time stay false: a test sets them to hand LOAM the sensor's values.
PointCloud scan(const World& w, const LidarModel& m, const Eigen::Isometry3d& start, const Eigen::Isometry3d& end,
	std::mt19937* rng = nullptr);
inline PointCloud scan(const World& w, const LidarModel& m, const Eigen::Isometry3d& pose, std::mt19937* rng = nullptr)
{
	return scan(w, m, pose, pose, rng);
}

/// A planar drive: straight and circular segments (length [m], curvature [1/m]).
class Path
{
   public:
	void add(double length, double curvature);
	double length() const { return total_; }
	/// Vehicle pose at arc length s (z = 0, heading along the path).
	Eigen::Isometry3d at(double s) const;

   private:
	struct Seg
	{
		double length, curvature, s0, x0, y0, yaw0;
	};
	std::vector<Seg> segs_;
	double total_ = 0;
};

/// Buildings along both sides of the path with gaps, poles, parked cars and trunks.
World urbanWorld(const Path& path, unsigned seed);
/// A straight corridor along x: two long walls and the ground, nothing else (degenerate along x).
World corridorWorld(double length, double half_width, double height);

/// LiDAR pose on the vehicle at arc length s: 1.73 m high, with a small body roll/pitch/bounce.
Eigen::Isometry3d lidarPoseAt(const Path& path, double s);
}  // namespace vlo::loam::test
