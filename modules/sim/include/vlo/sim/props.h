#pragma once
// Roadside objects. Each stands on a frame at ground level whose x axis runs along the road.
#include <vlo/sim/world.h>

#include <Eigen/Geometry>

namespace vlo::sim
{
class Rng;

/// Building of length x depth x height, sunk 0.5 m into the ground so slopes leave no gaps.
void addBuilding(World& w, const Eigen::Isometry3d& frame, double length, double depth, double height, int facade_tex,
	int roof_tex, double u_offset);
/// Parked car (4.5 x 1.8 m): body with wheel arches, cabin with windows.
void addCar(World& w, const Eigen::Isometry3d& frame, int body_tex, int cabin_tex);
/// Street lamp, optionally with a sign facing -y (towards the road when the frame's y points away).
void addPole(World& w, const Eigen::Isometry3d& frame, double height, int pole_tex, int sign_tex);
/// Tree: trunk plus one or two irregular canopies; `size` scales it (1 = a 7 m tree).
void addTree(World& w, const Eigen::Vector3d& base, double size, int bark_tex, int foliage_tex, Rng& rng);
/// Free-standing wall of the given length, height and thickness.
void addWall(World& w, const Eigen::Isometry3d& frame, double length, double height, double thickness, int tex);
}  // namespace vlo::sim
