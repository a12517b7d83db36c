#pragma once
// Points near which the map takes nothing (those of something that moved): a hash of cells of
// edge `radius`, each query looking through the 27 cells around it.
#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace vlo::loam
{
class NearPoints
{
   public:
	NearPoints(const std::vector<Eigen::Vector3f>& points, float radius);
	/// True if one of the points lies within the radius of p.
	bool near(const Eigen::Vector3f& p) const;
	bool empty() const { return cells_.empty(); }

   private:
	float radius_, inv_;
	std::unordered_map<std::uint64_t, std::vector<Eigen::Vector3f>> cells_;
};
}  // namespace vlo::loam
