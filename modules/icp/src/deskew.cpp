#include <vlo/icp/deskew.h>
#include <vlo/core/se3_twist.h>
#include <vlo/core/sweep_times.h>


namespace vlo::icp
{
Points deskewExact(const PointCloud& scan, const Eigen::Isometry3d& motion, double dt)
{
	Points out;
	out.reserve(scan.size());
	const bool moving = dt > 0 && !motion.isApprox(Eigen::Isometry3d::Identity()) && hasTimeSpread(scan);
	const Vector6d xi = logTwist(motion);
	for (const auto& p : scan)
	{
		const Eigen::Vector3d v(p.x, p.y, p.z);
		if (!moving)
		{
			out.push_back(v);
			continue;
		}
		out.push_back(expTwist(static_cast<double>(p.time) / dt * xi) * v);
	}
	return out;
}
}  // namespace vlo::icp
