#pragma once
// Tree crowns and bushes as a LiDAR sees them. The camera sees a crown's textured hull, but a laser
// beam goes between the leaves and returns from one at a random depth inside the crown (or from none),
// and a beam a few centimetres beside it hits another leaf: foliage returns do not repeat from sweep to
// sweep, which is what breaks LOAM's edge and plane features in vegetation.
#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace vlo::sim
{
class Rng;

class Foliage
{
   public:
	/// A crown: the ellipsoid (centre, radii) whose hull has bumps of relative size `roughness`.
	void add(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii, double roughness);
	std::size_t size() const { return crowns_.size(); }

	/// A beam o + r d (world frame, |d| = 1) hit a hull at `range`. If that point is on a crown's hull,
	/// the beam goes on for an exponential distance (mean `mean_depth`): `range` becomes the leaf it
	/// returns from, or the function returns false when the beam leaves the crown first (no return).
	/// Points not on a crown, and mean_depth 0, keep `range`.
	bool penetrate(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double mean_depth, Rng& rng, double& range) const;

	/// Whether a crown stands between `p` and the sun (unit vector `to_sun`, pointing up): the ray
	/// crosses a crown's hull for more than 0.2 m and does not enter it through one of the leaf gaps
	/// (where a fixed 3-D value noise with features 0.4 m apart is below `gap_fraction`, the sun
	/// passes between the leaves).
	bool shades(const Eigen::Vector3d& p, const Eigen::Vector3d& to_sun, double gap_fraction) const;

   private:
	struct Crown
	{
		Eigen::Vector3d centre, radii;
		double roughness;
	};
	std::vector<Crown> crowns_;
	std::unordered_map<int64_t, std::vector<int>> cells_;  // crowns overlapping each 8 m ground cell
	static int64_t cellKey(int64_t i, int64_t j) { return i * 1000003 + j; }
	const Crown* crownAt(const Eigen::Vector3d& p) const;
};
}  // namespace vlo::sim
