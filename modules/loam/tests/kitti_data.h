#pragma once
// Real data of the LOAM tests: shared-data archives unpacked once into the build tree, and KITTI
// Velodyne scans. Only for tests (the paths come from the test target's definitions).
#include <vlo/core/frame.h>
#include <vlo_test/shared_data.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace vlo::loam::test
{
/// The shared-data archive `name` unpacked into the build tree's test_data/loam (see vlo_test).
inline std::filesystem::path sharedData(const std::string& name, const std::string& top, const std::string& members,
	const std::string& ready)
{
	return vlo::test::sharedData("loam", name, top, members, ready);
}

/// A KITTI Velodyne scan (.bin: x, y, z, intensity as float32).
inline PointCloud readKittiBin(const std::filesystem::path& file)
{
	std::ifstream in(file, std::ios::binary);
	PointCloud pc;
	float v[4];
	while (in.read(reinterpret_cast<char*>(v), sizeof v)) pc.push_back(LidarPoint{v[0], v[1], v[2], v[3]});
	return pc;
}
}  // namespace vlo::loam::test
