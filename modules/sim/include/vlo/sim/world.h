#pragma once
// The simulated world: textured triangles grouped by texture. It becomes one MRPT scene (one
// CSetOfTexturedTriangles per texture: textured shaders render depth precisely, see the field notes)
// and also answers exact ray casts, which the tests use as the geometric truth.
#include <vlo/sim/foliage.h>
#include <vlo/sim/textures.h>

#include <mrpt/opengl/CSetOfObjects.h>

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace vlo::sim
{
struct Vertex
{
	Eigen::Vector3d p;
	double u = 0, v = 0;  ///< texture coordinates in repeats of the texture
};

/// A copy of `tex` with every grey level scaled by f (shading baked into the texture).
Texture darkened(const Texture& tex, double f);

class World
{
   public:
	/// Returns the texture id used by the add* calls. Faces drawn with a `shaded` texture get a darker
	/// copy of it when they face away from the sun (the renderer's lighting is not precise enough).
	int addTexture(Texture tex, bool shaded = true);
	const Texture& texture(int id) const { return textures_.at(id); }

	/// Triangle a, b, c; the front face is the one that sees them counter-clockwise.
	void addTriangle(int tex, const Vertex& a, const Vertex& b, const Vertex& c);
	/// Planar quad a-b-c-d (counter-clockwise seen from the front).
	void addQuad(int tex, const Vertex& a, const Vertex& b, const Vertex& c, const Vertex& d);
	/// Quad whose texture coordinates follow the texture's metric size: u along a->b, v along a->d,
	/// starting at (u0, v0) metres.
	void addMetricQuad(int tex, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
		const Eigen::Vector3d& d, double u0 = 0, double v0 = 0);

	/// Crowns and bushes, which the LiDAR sees as leaves inside the hull (addBlob registers them).
	Foliage& foliage() { return foliage_; }
	const Foliage& foliage() const { return foliage_; }

	std::size_t triangleCount() const;
	/// Builds the renderable scene content (call once; textures are uploaded on first render).
	/// `every_texture`: one object per texture even without triangles, for updateOpenGL.
	mrpt::opengl::CSetOfObjects::Ptr makeOpenGL(bool every_texture = false) const;
	/// Removes every triangle and keeps the textures: a world rebuilt each frame (moving vehicles).
	void clearTriangles();
	/// Replaces the triangles of `scene`, made by makeOpenGL(true) when the world had the same
	/// textures, with the current ones: the texture units stay, only the geometry is uploaded again.
	void updateOpenGL(mrpt::opengl::CSetOfObjects& scene) const;

	/// Exact first hit of the ray o + r d (|d| = 1), r in (0, max_range]. Brute force over chunks of
	/// triangles with bounding boxes: for tests and checks, not for sensor simulation.
	bool raycast(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_range, double& range) const;

	struct Tri
	{
		Vertex v[3];
	};

   private:
	struct Chunk
	{
		Eigen::Vector3d lo, hi;
		std::vector<const Tri*> tris;
	};
	std::vector<Texture> textures_;
	Foliage foliage_;
	std::vector<bool> shaded_;
	std::map<std::pair<int, int>, int> variants_;  // (texture, shade level) -> texture
	int shadedVariant(int tex, const Eigen::Vector3d& normal);
	std::vector<std::vector<Tri>> tris_;  // per texture
	mutable std::vector<Chunk> chunks_;  // built on the first raycast
	void buildChunks() const;
};
}  // namespace vlo::sim
