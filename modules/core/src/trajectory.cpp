#include <vlo/core/trajectory.h>

namespace vlo
{
Trajectory relativeToFirst(const Trajectory& traj)
{
	if (traj.empty()) return traj;
	const Eigen::Isometry3d inv0 = traj.front().pose.inverse();
	Trajectory out = traj;
	for (auto& p : out) p.pose = inv0 * p.pose;
	return out;
}

double pathLength(const Trajectory& traj)
{
	double len = 0;
	for (size_t i = 1; i < traj.size(); ++i)
		len += (traj[i].pose.translation() - traj[i - 1].pose.translation()).norm();
	return len;
}
}  // namespace vlo
