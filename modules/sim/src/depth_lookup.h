#pragma once
// Ray vs. rendered depth image. Inverse depth is affine in pixel coordinates on a plane, so the
// surface around a pixel is recovered exactly from its neighbours; at depth edges only the neighbours
// on the pixel's own surface are used (second differences tell which), so no mixed points appear.
#include <vlo/core/frame.h>
#include <vlo/sim/renderer.h>

#include <Eigen/Core>

namespace vlo::sim
{
class DepthLookup
{
   public:
	DepthLookup(const RenderedView& tile, const PinholeCamera& K) : t_(tile), K_(K) {}

	/// What a real beam's footprint meets around the hit (LidarErrors' input).
	struct Footprint
	{
		double radius_px = 0;  ///< in: the footprint's radius in pixels (0: not asked)
		double cos_incidence = 1;  ///< out: between the ray and the surface's normal
		/// out: depth of the other surface / the hit's, where a pixel within the footprint lies across a
		/// depth edge (the one that differs most); 0 if none (a neighbour on the sky is none).
		double edge_depth_ratio = 0;
	};
	/// First hit of the ray o + r d (view optical frame, |d| = 1); r and the pixel's gray on success,
	/// and with `footprint` the incidence and depth edge there.
	bool intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double& r, uint8_t& gray, Footprint* footprint = nullptr) const;

	/// Local surface n . P = 1 (optical frame) at the pixel nearest to (u, v); false if none. Near a
	/// crease (two surfaces meeting between pixel centres) the surface visible at (u, v) is chosen.
	bool plane(double u, double v, Eigen::Vector3d& n) const;

   private:
	const RenderedView& t_;
	PinholeCamera K_;
	double invDepth(int c, int r) const
	{
		if (c < 0 || r < 0 || c >= t_.width || r >= t_.height) return 0;
		const float z = t_.depthAt(r, c);
		return z > 0 ? 1.0 / z : 0;
	}
	double slope(int c, int r, int dc, int dr, double side) const;
	/// Footprint::edge_depth_ratio at pixel coordinates (u, v) on the plane n . P = 1.
	double edgeDepthRatio(double u, double v, const Eigen::Vector3d& n, double radius_px) const;
	/// Plane through pixel (c, r) from its slopes; `su`, `sv` pick the side at depth edges.
	bool pixelPlane(int c, int r, double su, double sv, Eigen::Vector3d& n) const;
	Eigen::Vector3d ray(double u, double v) const { return {(u - K_.cx) / K_.fx, (v - K_.cy) / K_.fy, 1.0}; }
};
}  // namespace vlo::sim
