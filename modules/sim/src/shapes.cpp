#include <vlo/sim/rng.h>
#include <vlo/sim/shapes.h>

#include <array>
#include <cmath>
#include <map>

namespace vlo::sim
{
void addBox(World& w, const Eigen::Isometry3d& f, double sx, double sy, double sz, int side_tex, int top_tex,
	double u0, double v0)
{
	const double x = sx / 2, y = sy / 2;
	auto P = [&](double a, double b, double c) { return Eigen::Vector3d(f * Eigen::Vector3d(a, b, c)); };
	// Each side face a-b-c-d: bottom-left, bottom-right, top-right, top-left seen from outside.
	w.addMetricQuad(side_tex, P(x, -y, 0), P(x, y, 0), P(x, y, sz), P(x, -y, sz), u0, v0);
	w.addMetricQuad(side_tex, P(-x, y, 0), P(-x, -y, 0), P(-x, -y, sz), P(-x, y, sz), u0 + sy, v0);
	w.addMetricQuad(side_tex, P(x, y, 0), P(-x, y, 0), P(-x, y, sz), P(x, y, sz), u0 + 2 * sy, v0);
	w.addMetricQuad(side_tex, P(-x, -y, 0), P(x, -y, 0), P(x, -y, sz), P(-x, -y, sz), u0 + 3 * sy, v0);
	if (top_tex >= 0) w.addMetricQuad(top_tex, P(-x, -y, sz), P(x, -y, sz), P(x, y, sz), P(-x, y, sz));
}

void addPrism(World& w, const Eigen::Isometry3d& f, double r, double h, int sides, int tex)
{
	const Texture& t = w.texture(tex);
	const double side = 2 * r * std::sin(M_PI / sides);
	for (int i = 0; i < sides; ++i)
	{
		const double a0 = 2 * M_PI * i / sides, a1 = 2 * M_PI * (i + 1) / sides;
		const Eigen::Vector3d p0 = f * Eigen::Vector3d(r * std::cos(a0), r * std::sin(a0), 0);
		const Eigen::Vector3d p1 = f * Eigen::Vector3d(r * std::cos(a1), r * std::sin(a1), 0);
		const Eigen::Vector3d up = f.linear() * Eigen::Vector3d(0, 0, h);
		const double u0 = i * side / t.width_m, u1 = (i + 1) * side / t.width_m, v1 = h / t.height_m;
		w.addQuad(tex, {p0, u0, 0}, {p1, u1, 0}, {p1 + up, u1, v1}, {p0 + up, u0, v1});
	}
}

void addProjectedTriangle(World& w, int tex, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
	const Texture& t = w.texture(tex);
	const Eigen::Vector3d n = (b - a).cross(c - a).cwiseAbs();
	int i = 0, j = 1;  // projection axes
	if (n.x() >= n.y() && n.x() >= n.z()) i = 1, j = 2;
	else if (n.y() >= n.z()) i = 0, j = 2;
	auto V = [&](const Eigen::Vector3d& p) { return Vertex{p, p[i] / t.width_m, p[j] / t.height_m}; };
	w.addTriangle(tex, V(a), V(b), V(c));
}

void addBlob(World& w, const Eigen::Vector3d& c, const Eigen::Vector3d& radii, double roughness, int tex, Rng& rng)
{
	// Icosahedron, subdivided twice.
	const double g = (1 + std::sqrt(5.0)) / 2;
	std::vector<Eigen::Vector3d> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
		{0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
	std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9},
		{5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
		{4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
	for (auto& p : v) p.normalize();
	std::map<std::pair<int, int>, int> mid;
	auto midpoint = [&](int a, int b) {
		const auto key = std::minmax(a, b);
		auto it = mid.find(key);
		if (it != mid.end()) return it->second;
		v.push_back((v[a] + v[b]).normalized());
		return mid[key] = static_cast<int>(v.size()) - 1;
	};
	for (int level = 0; level < 2; ++level)  // 320 faces
	{
		std::vector<std::array<int, 3>> f2;
		for (const auto& t : f)
		{
			const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
			f2.push_back({t[0], ab, ca}), f2.push_back({t[1], bc, ab}), f2.push_back({t[2], ca, bc}), f2.push_back({ab, bc, ca});
		}
		f.swap(f2);
	}
	for (auto& p : v) p = c + (p.cwiseProduct(radii)) * (1 + roughness * rng.uniform(-1, 1));
	w.foliage().add(c, radii, roughness);
	for (const auto& t : f) addProjectedTriangle(w, tex, v[t[0]], v[t[1]], v[t[2]]);
}
}  // namespace vlo::sim
