#include <vlo/icp/deskew.h>
#include <vlo/icp/voxel.h>
#include <vlo/loop/keyframe.h>

#include <cmath>
#include <unordered_set>

namespace vlo::loop
{
bool KeyframeSelector::take(const Eigen::Isometry3d& world_T_vehicle)
{
	if (!first_)
	{
		const Eigen::Isometry3d moved = last_.inverse() * world_T_vehicle;
		const double turned = Eigen::AngleAxisd(moved.linear()).angle();
		if (moved.translation().norm() < distance_ && turned < angle_) return false;
	}
	first_ = false;
	last_ = world_T_vehicle;
	return true;
}

ScanPoints keyframeScan(const PointCloud& scan, const Eigen::Isometry3d& lidar_motion, double dt,
	const Eigen::Isometry3d& vehicle_T_lidar, double voxel)
{
	PointCloud thinned;
	thinned.has_time = scan.has_time;
	thinned.has_ring = scan.has_ring;
	thinned.time_from_azimuth = scan.time_from_azimuth;
	std::unordered_set<icp::Voxel, icp::VoxelHasher> seen;
	seen.reserve(scan.size() / 4);
	for (const auto& p : scan)
	{
		const Eigen::Vector3d v(p.x, p.y, p.z);
		if (!v.allFinite()) continue;
		if (seen.insert(icp::voxelOf(v, voxel)).second) thinned.push_back(p);
	}
	const icp::Points deskewed = icp::deskewExact(thinned, lidar_motion, dt);
	ScanPoints out;
	out.reserve(deskewed.size());
	for (const auto& p : deskewed) out.push_back((vehicle_T_lidar * p).cast<float>());
	return out;
}
}  // namespace vlo::loop
