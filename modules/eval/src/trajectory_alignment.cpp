#include <vlo/eval/association.h>
#include <vlo/eval/trajectory_alignment.h>
#include <vlo/eval/umeyama.h>

#include <vector>

namespace vlo::eval
{
std::optional<Sim3> sim3ToGroundTruth(const Trajectory& gt, const Trajectory& est)
{
	const Association a = associate(gt, est);
	if (a.matched() < 3) return std::nullopt;
	std::vector<Eigen::Vector3d> src, dst;
	for (std::size_t i = 0; i < a.matched(); ++i)
		src.push_back(a.est[i].pose.translation()), dst.push_back(a.gt[i].pose.translation());
	return umeyama(src, dst, true);
}

Trajectory transformed(Trajectory traj, const Sim3& S)
{
	for (auto& p : traj)
	{
		p.pose.translation() = S * Eigen::Vector3d(p.pose.translation());
		p.pose.linear() = S.R * p.pose.linear();
	}
	return traj;
}
}  // namespace vlo::eval
