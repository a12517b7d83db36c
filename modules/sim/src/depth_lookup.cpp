#include "depth_lookup.h"

#include <cmath>

namespace vlo::sim
{
namespace
{
constexpr double kEdgeRelativeGap = 0.01;  // a depth 1 % off the hit's plane: another surface
}  // namespace

double DepthLookup::slope(int c, int r, int dc, int dr, double side) const
{
	const double w0 = invDepth(c, r), wm = invDepth(c - dc, r - dr), wp = invDepth(c + dc, r + dr);
	const double tol = 1e-3 * w0;
	const double gm = w0 - wm, gp = wp - w0;
	if (wm > 0 && wp > 0 && std::abs(gm - gp) <= tol) return 0.5 * (gm + gp);
	// One side only: the one whose next pixel continues the same slope (same surface).
	const double wmm = invDepth(c - 2 * dc, r - 2 * dr), wpp = invDepth(c + 2 * dc, r + 2 * dr);
	const bool okm = wm > 0 && wmm > 0 && std::abs((wm - wmm) - gm) <= tol;
	const bool okp = wp > 0 && wpp > 0 && std::abs((wpp - wp) - gp) <= tol;
	if (okm && okp) return side >= 0 ? gp : gm;
	if (okm) return gm;
	if (okp) return gp;
	return 0;  // a sliver (pole far away): take it as facing the camera
}

bool DepthLookup::pixelPlane(int c, int r, double su, double sv, Eigen::Vector3d& n) const
{
	const double w0 = invDepth(c, r);
	if (w0 <= 0) return false;
	const double gu = slope(c, r, 1, 0, su), gv = slope(c, r, 0, 1, sv);
	// w = w0 + gu (u - c) + gv (v - r), with u = fx x + cx, v = fy y + cy (normalised x, y).
	n = Eigen::Vector3d(gu * K_.fx, gv * K_.fy, w0 - gu * (c - K_.cx) - gv * (r - K_.cy));
	return true;
}

bool DepthLookup::plane(double u, double v, Eigen::Vector3d& n) const
{
	const int c = static_cast<int>(std::lround(u)), r = static_cast<int>(std::lround(v));
	if (!pixelPlane(c, r, u - c, v - r, n)) return false;
	// Across the nearer pixel border in u and in v: if the neighbour's surface crosses this one
	// between the two centres (a crease, not an occlusion edge), the visible surface at (u, v) is
	// the envelope that agrees with both centres: the nearer one for a concave crease (a wall's
	// foot), the farther one for a convex edge (a box corner).
	const int steps[2][2] = {{u >= c ? 1 : -1, 0}, {0, v >= r ? 1 : -1}};
	for (const auto& s : steps)
	{
		const int cn = c + s[0], rn = r + s[1];
		Eigen::Vector3d nb;
		if (!pixelPlane(cn, rn, s[0] != 0 ? s[0] : u - c, s[1] != 0 ? s[1] : v - r, nb)) continue;
		const Eigen::Vector3d rc = ray(c, r), rnb = ray(cn, rn), rs = ray(u, v);
		const double dc = n.dot(rc) - nb.dot(rc), dn = n.dot(rnb) - nb.dot(rnb);
		if (!(dc * dn < 0)) continue;
		const bool concave = dc > 0;
		const double wa = n.dot(rs), wb = nb.dot(rs);
		if (concave ? wb > wa : wb < wa) n = nb;
	}
	return true;
}

double DepthLookup::edgeDepthRatio(double u, double v, const Eigen::Vector3d& n, double radius_px) const
{
	// A pixel within the footprint is on another surface if its depth is off the hit's plane there.
	const double w0 = n.dot(ray(u, v));
	if (w0 <= 0) return 0;
	double ratio = 0, largest = kEdgeRelativeGap;
	const double around[4][2] = {{radius_px, 0}, {-radius_px, 0}, {0, radius_px}, {0, -radius_px}};
	for (const auto& a : around)
	{
		const int c = static_cast<int>(std::lround(u + a[0])), r = static_cast<int>(std::lround(v + a[1]));
		const double w = invDepth(c, r), planar = n.dot(ray(c, r));
		if (w <= 0 || planar <= 0) continue;
		const double off = std::abs(planar / w - 1);
		if (off > largest) largest = off, ratio = w0 / w;
	}
	return ratio;
}

bool DepthLookup::intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double& r, uint8_t& gray, Footprint* footprint) const
{
	if (d.z() <= 1e-6) return false;
	// Start where the direction alone points (exact when o = 0), then follow the hit point.
	double u = K_.fx * d.x() / d.z() + K_.cx, v = K_.fy * d.y() / d.z() + K_.cy;
	for (int it = 0; it < 4; ++it)
	{
		Eigen::Vector3d n;
		if (!plane(u, v, n)) return false;
		const double nd = n.dot(d);
		if (std::abs(nd) < 1e-12) return false;
		r = (1.0 - n.dot(o)) / nd;
		if (r <= 0) return false;
		const Eigen::Vector3d P = o + r * d;
		if (P.z() <= 1e-6) return false;
		const double u2 = K_.fx * P.x() / P.z() + K_.cx, v2 = K_.fy * P.y() / P.z() + K_.cy;
		const bool same = std::lround(u2) == std::lround(u) && std::lround(v2) == std::lround(v);
		u = u2, v = v2;
		if (same)
		{
			const int c = static_cast<int>(std::lround(u)), row = static_cast<int>(std::lround(v));
			gray = t_.gray.empty() ? 0 : t_.gray[static_cast<std::size_t>(row) * t_.width + c];
			if (footprint && footprint->radius_px > 0)
			{
				footprint->cos_incidence = std::abs(nd) / n.norm();
				footprint->edge_depth_ratio = edgeDepthRatio(u, v, n, footprint->radius_px);
			}
			return true;
		}
	}
	return false;
}
}  // namespace vlo::sim
