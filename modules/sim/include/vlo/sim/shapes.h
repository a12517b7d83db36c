#pragma once
// Solid shapes made of textured triangles, placed by a frame whose origin is the centre of the
// footprint at ground level (x along the length, y across, z up).
#include <vlo/sim/world.h>

#include <Eigen/Geometry>

namespace vlo::sim
{
class Rng;

/// Box of length sx (x), width sy (y), height sz (z) standing on the frame's origin. Side faces get
/// metric texture coordinates (v = 0 at the bottom plus v0, u starting at u0); the top gets `top_tex`
/// (-1: no top). No bottom face.
void addBox(World& w, const Eigen::Isometry3d& frame, double sx, double sy, double sz, int side_tex, int top_tex,
	double u0 = 0, double v0 = 0);
/// Upright prism (n sides, circumradius r, height h) on the frame's origin, texture wrapped around.
void addPrism(World& w, const Eigen::Isometry3d& frame, double r, double h, int sides, int tex);
/// Irregular closed blob (tree canopy, bush): a subdivided icosahedron with radii (rx, ry, rz) and
/// random bumps of relative size `roughness`, centred at c; registered as foliage (see foliage.h).
void addBlob(World& w, const Eigen::Vector3d& c, const Eigen::Vector3d& radii, double roughness, int tex, Rng& rng);
/// Triangle with texture coordinates projected on the plane its normal faces most (no seams).
void addProjectedTriangle(World& w, int tex, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);
}  // namespace vlo::sim
