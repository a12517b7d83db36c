#pragma once
// The road centre line: stations about 1 m apart with position (on the road surface), heading and
// grade, plus a spatial index so that world building can ask "how far is this from any road?".
#include <Eigen/Core>
#include <unordered_map>
#include <vector>

namespace vlo::sim
{
class Rng;

struct Station
{
	double s = 0;  ///< arc length (m)
	Eigen::Vector3d p = Eigen::Vector3d::Zero();  ///< centre of the road surface
	double heading = 0;  ///< rad, counter-clockwise from world x
	double grade = 0;  ///< dz/ds
	double curvature = 0;  ///< 1/m, positive to the left
};

class Road
{
   public:
	Road() = default;
	/// `closed`: a circuit whose last station lies on the first (arc lengths wrap around its length).
	explicit Road(std::vector<Station> stations, bool closed = false);
	const std::vector<Station>& stations() const { return st_; }
	double length() const { return st_.empty() ? 0 : st_.back().s; }
	bool closed() const { return closed_; }
	/// Distance along the road between arc lengths a and b (the shorter way round on a circuit).
	double arcDistance(double a, double b) const;

	/// Interpolated station at arc length s (clamped to the road; taken modulo the length on a circuit).
	Station at(double s) const;
	/// Point at arc length s, `lateral` metres to the left of the centre line, `up` above the surface.
	Eigen::Vector3d point(double s, double lateral, double up = 0) const;
	/// Nearest station to xy among stations within `radius` whose arc length differs from `s_self` by
	/// more than `exclude` (exclude = 0: all); nullptr if none.
	const Station* nearest(const Eigen::Vector2d& xy, double radius, double s_self = 0, double exclude = 0) const;

   private:
	std::vector<Station> st_;
	bool closed_ = false;
	std::unordered_map<int64_t, std::vector<int>> grid_;  // 8 m cells -> station indices
	static constexpr double kCell = 8.0;
	static int64_t key(int64_t ix, int64_t iy) { return ix * 1000003LL + iy; }
};

/// How a generated road bends and climbs.
struct RoadStyle
{
	double max_curvature = 1 / 35.0;  ///< sharpest bend (1/m)
	double min_curvature = 1 / 250.0;  ///< gentlest bend
	double straight_fraction = 0.5;  ///< share of straight pieces
	double piece_min = 25, piece_max = 90;  ///< piece length (m)
	double grade_amplitude = 0.035;  ///< max grade (rise/run)
	/// Arc-length interval [from, to) that is kept straight and level (corridor), empty if from >= to.
	double straight_from = 0, straight_to = 0;
};

/// Integrates a random, smooth curvature and grade profile into stations every 1 m from the origin
/// heading along world x.
Road generateRoad(const RoadStyle& style, double length, Rng& rng);

/// A straight, level road along world x from the origin, stations every 1 m.
Road straightRoad(double length);

/// Road through given centre-line points (for instance a KITTI drive shifted sideways), resampled
/// every `step` metres, extended straight by `extend` metres at both ends.
Road roadThrough(const std::vector<Eigen::Vector3d>& points, double extend, double step = 1.0);
}  // namespace vlo::sim
