#pragma once
// The LiDAR benchmarks' drive: a synthetic urban street (15 m straight, then a bend), ray cast once per
// sensor model and kept for the whole process, so every method and stage is timed on the same scans.
#include <map>
#include <random>
#include <vector>

#include "synthetic_world.h"
#include "test_helpers.h"

namespace vlo::loam::test
{
/// `frames` scans of the HDL-64E (`hdl`) or the VLP-16, one metre apart.
inline const std::vector<PointCloud>& urbanStreetScans(bool hdl, int frames)
{
	static std::map<bool, std::vector<PointCloud>> cache;
	auto& s = cache[hdl];
	if (s.empty())
	{
		Path path;
		path.add(15, 0.0);
		path.add(40, 1.0 / 35);
		const World world = urbanWorld(path, 3);
		LidarModel m = hdl ? hdl64() : vlp16();
		m.noise_sigma = 0.01;
		std::mt19937 rng(5);
		for (int i = 0; i < frames; ++i) s.push_back(scan(world, m, lidarPoseAt(path, 1.0 * i), &rng));
	}
	return s;
}
}  // namespace vlo::loam::test
