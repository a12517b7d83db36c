#include <vlo/core/error.h>
#include <vlo/io/kitti_oxts.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace vlo::io
{
namespace
{
constexpr double kEarthRadius = 6378137.0;  // [m] the devkit's WGS84 equatorial radius
}

OxtsRecord readOxtsRecord(const std::string& path)
{
	std::ifstream in(path);
	if (!in) failInput(path, "cannot open OXTS record");
	std::string line;
	std::getline(in, line);
	std::istringstream values(line);
	std::vector<double> v;
	for (double x; values >> x;) v.push_back(x);
	if (v.size() < 6 || !values.eof())
		failInput(path, "not an OXTS record: expected 30 numbers (lat lon alt roll pitch yaw ...), read " + std::to_string(v.size()));
	for (int k = 0; k < 6; ++k)
		if (!std::isfinite(v[k])) failInput(path, "OXTS record with a non-finite position or orientation");
	if (std::fabs(v[0]) >= 90) failInput(path, "latitude " + std::to_string(v[0]) + " is not in (-90, 90)");
	return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

std::vector<Eigen::Isometry3d> oxtsPoses(const std::vector<OxtsRecord>& records)
{
	std::vector<Eigen::Isometry3d> poses;
	if (records.empty()) return poses;
	const double scale = std::cos(records.front().lat * M_PI / 180.0);
	Eigen::Isometry3d first_inv = Eigen::Isometry3d::Identity();
	for (const OxtsRecord& r : records)
	{
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.translation() = Eigen::Vector3d(scale * r.lon * M_PI * kEarthRadius / 180.0,
			scale * kEarthRadius * std::log(std::tan((90.0 + r.lat) * M_PI / 360.0)), r.alt);
		T.linear() = (Eigen::AngleAxisd(r.yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(r.pitch, Eigen::Vector3d::UnitY()) *
			Eigen::AngleAxisd(r.roll, Eigen::Vector3d::UnitX()))
						 .toRotationMatrix();
		if (poses.empty()) first_inv = T.inverse();
		poses.push_back(first_inv * T);
	}
	return poses;
}

Trajectory oxtsVelodyneTrajectory(
	const std::vector<OxtsRecord>& records, const std::vector<double>& times, const Eigen::Isometry3d& velo_T_imu)
{
	Trajectory traj;
	const auto imu = oxtsPoses(records);
	for (std::size_t i = 0; i < imu.size() && i < times.size(); ++i)
		traj.push_back({times[i], velo_T_imu * imu[i] * velo_T_imu.inverse()});
	return traj;
}
}  // namespace vlo::io
