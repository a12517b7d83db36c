#include <vlo/icp/voxel_map.h>

#include <limits>

namespace vlo::icp
{
VoxelMap::VoxelMap(double voxel_size, int max_points_per_voxel, double radius)
	: voxel_size_(voxel_size),
	  radius_(radius),
	  // N points spread evenly over a voxel face are about size / sqrt(N) apart.
	  min_spacing2_(voxel_size * voxel_size / max_points_per_voxel),
	  max_points_(static_cast<std::size_t>(max_points_per_voxel))
{
}

void VoxelMap::update(const Points& points, const Eigen::Isometry3d& pose)
{
	Points inMap;
	inMap.reserve(points.size());
	for (const auto& p : points) inMap.push_back(pose * p);
	addPoints(inMap);
	removeFarFrom(pose.translation());
}

void VoxelMap::addPoints(const Points& map_points)
{
	for (const auto& p : map_points)
	{
		Points& cell = voxels_[voxelOf(p, voxel_size_)];
		if (cell.size() >= max_points_) continue;
		bool crowded = false;
		for (const auto& q : cell)
			if ((q - p).squaredNorm() < min_spacing2_)
			{
				crowded = true;
				break;
			}
		if (!crowded) cell.push_back(p);
	}
}

void VoxelMap::removeFarFrom(const Eigen::Vector3d& origin)
{
	const double r2 = radius_ * radius_;
	for (auto it = voxels_.begin(); it != voxels_.end();)
	{
		if ((it->second.front() - origin).squaredNorm() >= r2)
			it = voxels_.erase(it);
		else
			++it;
	}
}

bool VoxelMap::nearest(const Eigen::Vector3d& q, Eigen::Vector3d& closest, double& distance2, double max_distance2) const
{
	const Voxel c = voxelOf(q, voxel_size_);
	// How far q is inside its voxel from the lower and the upper face, per axis.
	const Eigen::Vector3d lo = q - voxel_size_ * Eigen::Vector3d(c.x, c.y, c.z);
	const Eigen::Vector3d hi = Eigen::Vector3d::Constant(voxel_size_) - lo;
	const auto gap = [&](int axis, int d) { return d < 0 ? lo[axis] : (d > 0 ? hi[axis] : 0.0); };
	bool found = false;
	distance2 = max_distance2;
	// Own voxel first, then a neighbour only when its box is closer than the best point so far: the
	// result is the exact nearest point of the 27 voxels, with far fewer hash look-ups.
	static constexpr int kOrder[3] = {0, -1, 1};
	for (int dx : kOrder)
		for (int dy : kOrder)
			for (int dz : kOrder)
			{
				const double g = gap(0, dx), h = gap(1, dy), k = gap(2, dz);
				if (g * g + h * h + k * k >= distance2) continue;
				const auto it = voxels_.find({c.x + dx, c.y + dy, c.z + dz});
				if (it == voxels_.end()) continue;
				for (const auto& p : it->second)
				{
					const double d2 = (p - q).squaredNorm();
					if (d2 < distance2)
					{
						distance2 = d2;
						closest = p;
						found = true;
					}
				}
			}
	return found;
}

std::size_t VoxelMap::pointCount() const
{
	std::size_t n = 0;
	for (const auto& [v, cell] : voxels_) n += cell.size();
	return n;
}

Points VoxelMap::points() const
{
	Points all;
	all.reserve(pointCount());
	for (const auto& [v, cell] : voxels_) all.insert(all.end(), cell.begin(), cell.end());
	return all;
}
}  // namespace vlo::icp
