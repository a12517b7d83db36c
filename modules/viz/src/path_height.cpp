#include "path_height.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace vlo::viz
{
std::vector<float> heightAbovePath(const PointCloud& pts, const Trajectory& path, double radius)
{
	std::vector<float> out(pts.size());
	if (path.empty())
	{
		for (size_t i = 0; i < pts.size(); ++i) out[i] = pts[i].z;
		return out;
	}
	// Poses about 2 m apart, bucketed in a grid of `radius`-sized cells: 3x3 cells cover the radius.
	std::vector<Eigen::Vector3d> poses{path.front().pose.translation()};
	for (const auto& p : path)
		if ((p.pose.translation() - poses.back()).norm() >= 2.0) poses.push_back(p.pose.translation());
	auto key = [&](double x, double y) {
		return (std::int64_t(std::floor(x / radius)) << 32) ^ (std::int64_t(std::floor(y / radius)) & 0xffffffff);
	};
	std::unordered_map<std::int64_t, std::vector<int>> grid;
	for (int k = 0; k < int(poses.size()); ++k) grid[key(poses[k].x(), poses[k].y())].push_back(k);
	std::vector<double> zs;
	for (const auto& p : poses) zs.push_back(p.z());
	std::nth_element(zs.begin(), zs.begin() + zs.size() / 2, zs.end());
	const double median = zs[zs.size() / 2];

	for (size_t i = 0; i < pts.size(); ++i)
	{
		const auto& q = pts[i];
		double best = radius * radius, z = median;
		for (int dx = -1; dx <= 1; ++dx)
			for (int dy = -1; dy <= 1; ++dy)
			{
				const auto it = grid.find(key(q.x + dx * radius, q.y + dy * radius));
				if (it == grid.end()) continue;
				for (int k : it->second)
				{
					const double d2 = std::pow(poses[k].x() - q.x, 2) + std::pow(poses[k].y() - q.y, 2);
					if (d2 < best) best = d2, z = poses[k].z();
				}
			}
		out[i] = float(q.z - z);
	}
	return out;
}
}  // namespace vlo::viz
