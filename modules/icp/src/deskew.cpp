#include <vlo/icp/deskew.h>
#include <vlo/core/se3_twist.h>

#include <cmath>

namespace vlo::icp
{
const char* toString(SweepTimes t)
{
	switch (t)
	{
		case SweepTimes::PerPoint: return "time";
		case SweepTimes::Azimuth: return "azimuth";
		case SweepTimes::None: break;
	}
	return "off";
}

Eigen::Isometry3d scaleMotion(const Eigen::Isometry3d& motion, double s)
{
	return expTwist(s * logTwist(motion));
}

double azimuthTime(const LidarPoint& p, double dt)
{
	return -std::atan2(static_cast<double>(p.y), static_cast<double>(p.x)) / (2.0 * M_PI) * dt;
}

Points deskew(const PointCloud& scan, SweepTimes times, const Eigen::Isometry3d& motion, double dt)
{
	Points out;
	out.reserve(scan.size());
	const bool moving = times != SweepTimes::None && dt > 0 && !motion.isApprox(Eigen::Isometry3d::Identity());
	const Vector6d xi = logTwist(motion);
	for (const auto& p : scan)
	{
		const Eigen::Vector3d v(p.x, p.y, p.z);
		if (!moving)
		{
			out.push_back(v);
			continue;
		}
		const double s = (times == SweepTimes::PerPoint ? static_cast<double>(p.time) : azimuthTime(p, dt)) / dt;
		out.push_back(expTwist(s * xi) * v);
	}
	return out;
}
}  // namespace vlo::icp
