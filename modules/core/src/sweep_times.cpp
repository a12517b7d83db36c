#include <vlo/core/se3_twist.h>
#include <vlo/core/sweep_times.h>

#include <algorithm>
#include <cmath>

namespace vlo
{
double SpinningSweep::timeAt(double azimuth) const
{
	// Fraction of the turn since the seam, which lies frame_fraction of a turn before frame_azimuth.
	const double turned = (clockwise ? frame_azimuth - azimuth : azimuth - frame_azimuth) / (2 * M_PI) + frame_fraction;
	const double s = turned - std::floor(turned);
	return (s - frame_fraction) * period;
}

void setTimesFromAzimuth(PointCloud& scan, const SpinningSweep& sweep)
{
	for (LidarPoint& p : scan) p.time = static_cast<float>(sweep.timeAt(std::atan2(double(p.y), double(p.x))));
	scan.has_time = true;
	scan.time_from_azimuth = true;
}

void moveToFrameTime(PointCloud& scan, const Eigen::Isometry3d& motion, double dt)
{
	if (!(dt > 0)) return;
	const Vector6d xi = logTwist(motion) / dt;  // per second: translation, then rotation
	const Eigen::Vector3f v = xi.head<3>().cast<float>(), w = xi.tail<3>().cast<float>();
	for (LidarPoint& p : scan)
	{
		const Eigen::Vector3f q(p.x, p.y, p.z);
		const Eigen::Vector3f moved = q + p.time * (w.cross(q) + v);
		p.x = moved.x(), p.y = moved.y(), p.z = moved.z(), p.time = 0;
	}
}

bool hasTimeSpread(const PointCloud& scan)
{
	return scan.has_time &&
		std::any_of(scan.begin(), scan.end(), [&](const LidarPoint& p) { return p.time != scan.front().time; });
}
}  // namespace vlo
