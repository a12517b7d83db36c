#include <vlo/sim/world.h>

#include <mrpt/opengl/CSetOfTexturedTriangles.h>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vlo::sim
{
namespace
{
/// MRPT 2.5 samples textures without mipmaps, which aliases: distant texture detail flickers from
/// frame to frame and makes features that do not exist. Once MRPT has uploaded the texture (first
/// draw), build the mipmap chain and switch to trilinear filtering.
class MipmappedTriangles : public mrpt::opengl::CSetOfTexturedTriangles
{
   public:
	void render(const mrpt::opengl::CRenderizable::RenderContext& rc) const override
	{
		CSetOfTexturedTriangles::render(rc);
		if (mipmapped_ || getTrianglesCount() == 0) return;  // an empty object binds no texture
		GLint tex = 0;
		glGetIntegerv(GL_TEXTURE_BINDING_2D, &tex);  // MRPT leaves its texture bound
		if (tex == 0) return;
		glGenerateMipmap(GL_TEXTURE_2D);
		glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
		mipmapped_ = true;
	}

   private:
	mutable bool mipmapped_ = false;
};

/// The triangles of one texture as MRPT draws them.
void fillTriangles(mrpt::opengl::CSetOfTexturedTriangles& obj, const std::vector<World::Tri>& tris)
{
	obj.clearTriangles();
	for (const World::Tri& tri : tris)
	{
		mrpt::opengl::TTriangle T;
		for (int k = 0; k < 3; ++k)
		{
			const auto& p = tri.v[k].p;
			T.vertex(k) = mrpt::math::TPoint3Df(float(p.x()), float(p.y()), float(p.z()));
			T.u(k) = static_cast<float>(tri.v[k].u);
			T.v(k) = static_cast<float>(tri.v[k].v);
			T.vertices[k].setColor(mrpt::img::TColor(255, 255, 255, 255));
		}
		T.computeNormals();
		obj.insertTriangle(T);
	}
}
}  // namespace

Texture darkened(const Texture& tex, double f)
{
	Texture t = tex;
	t.image = t.image.makeDeepCopy();
	for (unsigned r = 0; r < t.image.getHeight(); ++r)
	{
		auto* row = t.image.ptrLine<uint8_t>(r);
		for (unsigned c = 0; c < t.image.getWidth() * t.image.channelCount(); ++c) row[c] = static_cast<uint8_t>(row[c] * f + 0.5);
	}
	return t;
}

int World::addTexture(Texture tex, bool shaded)
{
	textures_.push_back(std::move(tex));
	tris_.emplace_back();
	shaded_.push_back(shaded);
	return static_cast<int>(textures_.size()) - 1;
}

int World::shadedVariant(int tex, const Eigen::Vector3d& normal)
{
	if (!shaded_.at(tex)) return tex;
	// Overcast sky with the sun high in the south-east: up-facing surfaces keep the texture, walls
	// turned to the sun get 82 %, the others 64 %. Few levels, because MRPT binds every texture to
	// its own texture unit (192 in llvmpipe, never released).
	static const Eigen::Vector3d sun = Eigen::Vector3d(-0.45, 0.3, 0.84).normalized();
	const double light = 0.55 + 0.45 * std::max(0.0, normal.normalized().dot(sun));
	const int level = light >= 0.86 ? 0 : light >= 0.7 ? 1
													   : 2;
	if (level == 0) return tex;
	const auto key = std::make_pair(tex, level);
	const auto it = variants_.find(key);
	if (it != variants_.end()) return it->second;
	const int id = addTexture(darkened(textures_[tex], level == 1 ? 0.82 : 0.64), false);
	variants_[key] = id;
	return id;
}

void World::addTriangle(int tex, const Vertex& a, const Vertex& b, const Vertex& c)
{
	tex = shadedVariant(tex, (b.p - a.p).cross(c.p - a.p));
	tris_.at(tex).push_back(Tri{{a, b, c}});
	chunks_.clear();
}

void World::addQuad(int tex, const Vertex& a, const Vertex& b, const Vertex& c, const Vertex& d)
{
	addTriangle(tex, a, b, c);
	addTriangle(tex, a, c, d);
}

void World::addMetricQuad(int tex, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
	const Eigen::Vector3d& d, double u0, double v0)
{
	const Texture& t = textures_.at(tex);
	const double lu = (b - a).norm(), lv = (d - a).norm();
	const double su = 1.0 / t.width_m, sv = 1.0 / t.height_m;
	addQuad(tex, {a, u0 * su, v0 * sv}, {b, (u0 + lu) * su, v0 * sv}, {c, (u0 + lu) * su, (v0 + lv) * sv},
		{d, u0 * su, (v0 + lv) * sv});
}

std::size_t World::triangleCount() const
{
	std::size_t n = 0;
	for (const auto& v : tris_) n += v.size();
	return n;
}

mrpt::opengl::CSetOfObjects::Ptr World::makeOpenGL(bool every_texture) const
{
	// MRPT 2.5 gives each textured object its own texture unit for the life of the process (192 in
	// llvmpipe); beyond that it silently draws wrong textures, so fail clearly instead.
	static int unitsUsed = 0;
	int needed = 0;
	for (const auto& t : tris_) needed += every_texture || !t.empty();
	if (unitsUsed + needed > 190)
		throw std::runtime_error("MRPT texture units exhausted: at most ~190 textures per process (this world needs " +
			std::to_string(needed) + ", " + std::to_string(unitsUsed) + " already used by earlier worlds)");
	unitsUsed += needed;
	auto root = mrpt::opengl::CSetOfObjects::Create();
	for (std::size_t t = 0; t < textures_.size(); ++t)
	{
		if (tris_[t].empty() && !every_texture) continue;
		auto obj = std::make_shared<MipmappedTriangles>();
		fillTriangles(*obj, tris_[t]);
		obj->assignImage(textures_[t].image);
		obj->enableTextureLinearInterpolation(true);
		// MRPT 2.5's lit textured shader runs at medium precision: depth off by ~0.3 % and vertices
		// jitter. Unlit is exact; shading is baked into texture variants instead (see addTriangle).
		obj->enableLight(false);
		root->insert(obj);
	}
	return root;
}

void World::clearTriangles()
{
	for (auto& list : tris_) list.clear();
	chunks_.clear();
}

void World::updateOpenGL(mrpt::opengl::CSetOfObjects& scene) const
{
	if (scene.size() != tris_.size()) throw std::logic_error("World::updateOpenGL: the scene was made for other textures");
	std::size_t t = 0;
	for (const auto& obj : scene) fillTriangles(dynamic_cast<mrpt::opengl::CSetOfTexturedTriangles&>(*obj), tris_[t++]);
}

void World::buildChunks() const
{
	chunks_.clear();
	constexpr std::size_t kChunk = 32;
	for (const auto& list : tris_)
		for (std::size_t i = 0; i < list.size(); i += kChunk)
		{
			Chunk c;
			c.lo.setConstant(std::numeric_limits<double>::max());
			c.hi = -c.lo;
			for (std::size_t j = i; j < std::min(list.size(), i + kChunk); ++j)
			{
				c.tris.push_back(&list[j]);
				for (const auto& v : list[j].v) c.lo = c.lo.cwiseMin(v.p), c.hi = c.hi.cwiseMax(v.p);
			}
			chunks_.push_back(std::move(c));
		}
}

bool World::raycast(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double max_range, double& range) const
{
	if (chunks_.empty()) buildChunks();
	const Eigen::Vector3d inv = d.cwiseInverse();
	double best = max_range;
	bool hit = false;
	for (const Chunk& c : chunks_)
	{
		// Slab test against the chunk's box.
		double t0 = 0, t1 = best;
		for (int a = 0; a < 3 && t0 <= t1; ++a)
		{
			double ta = (c.lo[a] - o[a]) * inv[a], tb = (c.hi[a] - o[a]) * inv[a];
			if (ta > tb) std::swap(ta, tb);
			t0 = std::max(t0, ta), t1 = std::min(t1, tb);
		}
		if (t0 > t1) continue;
		for (const Tri* tri : c.tris)
		{
			// Moller-Trumbore.
			const Eigen::Vector3d e1 = tri->v[1].p - tri->v[0].p, e2 = tri->v[2].p - tri->v[0].p;
			const Eigen::Vector3d pv = d.cross(e2);
			const double det = e1.dot(pv);
			if (std::abs(det) < 1e-12) continue;
			const Eigen::Vector3d tv = o - tri->v[0].p;
			const double u = tv.dot(pv) / det;
			if (u < 0 || u > 1) continue;
			const Eigen::Vector3d qv = tv.cross(e1);
			const double v = d.dot(qv) / det;
			if (v < 0 || u + v > 1) continue;
			const double t = e2.dot(qv) / det;
			if (t > 1e-9 && t < best) best = t, hit = true;
		}
	}
	if (hit) range = best;
	return hit;
}
}  // namespace vlo::sim
