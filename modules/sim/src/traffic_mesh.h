#pragma once
// What the camera sees of the traffic: the vehicles' boxes at one instant, as textured triangles that
// are replaced every frame inside objects created once (MRPT never frees a texture unit, so the
// textures are uploaded once and only the geometry changes).
#include <vlo/sim/traffic.h>
#include <vlo/sim/world.h>

#include <mrpt/opengl/CSetOfObjects.h>

namespace vlo::sim
{
class TrafficMesh
{
   public:
	/// The vehicles' textures (see vehicle_tex), seeded.
	explicit TrafficMesh(uint64_t seed);
	/// The object to insert into the scene once.
	mrpt::opengl::CSetOfObjects::Ptr object() const { return gl_; }
	/// Moves the vehicles to where they are at time t.
	void update(const Traffic& traffic, double t);
	/// Mean grey level (0-255) of a texture slot: the LiDAR's intensity on that face.
	uint8_t gray(int slot) const { return gray_.at(static_cast<std::size_t>(slot)); }

   private:
	World mesh_;
	mrpt::opengl::CSetOfObjects::Ptr gl_;
	std::vector<uint8_t> gray_;
};
}  // namespace vlo::sim
