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
	OxtsRecord r{v[0], v[1], v[2], v[3], v[4], v[5]};
	if (v.size() >= 11 && std::isfinite(v[6]) && std::isfinite(v[7]) && std::isfinite(v[10]))
		r.vn = v[6], r.ve = v[7], r.vu = v[10], r.has_velocity = true;
	return r;
}

namespace
{
Eigen::Matrix3d orientation(const OxtsRecord& r)
{
	return (Eigen::AngleAxisd(r.yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(r.pitch, Eigen::Vector3d::UnitY()) *
		Eigen::AngleAxisd(r.roll, Eigen::Vector3d::UnitX()))
		.toRotationMatrix();
}

/// World poses (x east, y north, z up) relative to the first.
std::vector<Eigen::Isometry3d> relativeToFirst(const std::vector<OxtsRecord>& records, const std::vector<Eigen::Vector3d>& positions)
{
	std::vector<Eigen::Isometry3d> poses;
	Eigen::Isometry3d first_inv = Eigen::Isometry3d::Identity();
	for (std::size_t i = 0; i < records.size(); ++i)
	{
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.translation() = positions[i];
		T.linear() = orientation(records[i]);
		if (poses.empty()) first_inv = T.inverse();
		poses.push_back(first_inv * T);
	}
	return poses;
}
}  // namespace

std::vector<Eigen::Isometry3d> oxtsPoses(const std::vector<OxtsRecord>& records)
{
	if (records.empty()) return {};
	const double scale = std::cos(records.front().lat * M_PI / 180.0);
	std::vector<Eigen::Vector3d> positions;
	for (const OxtsRecord& r : records)
		positions.emplace_back(scale * r.lon * M_PI * kEarthRadius / 180.0,
			scale * kEarthRadius * std::log(std::tan((90.0 + r.lat) * M_PI / 360.0)), r.alt);
	return relativeToFirst(records, positions);
}

std::vector<Eigen::Isometry3d> oxtsDeadReckonedPoses(const std::vector<OxtsRecord>& records, const std::vector<double>& times)
{
	if (records.empty() || times.size() != records.size()) return {};
	const auto velocity = [](const OxtsRecord& r) { return Eigen::Vector3d(r.ve, r.vn, r.vu); };
	std::vector<Eigen::Vector3d> positions{Eigen::Vector3d::Zero()};
	for (std::size_t i = 0; i < records.size(); ++i)
	{
		if (!records[i].has_velocity) return {};
		if (i == 0) continue;
		const double dt = times[i] - times[i - 1];
		if (!(dt > 0)) return {};
		positions.push_back(positions.back() + 0.5 * dt * (velocity(records[i - 1]) + velocity(records[i])));
	}
	return relativeToFirst(records, positions);
}

Trajectory velodyneTrajectory(
	const std::vector<Eigen::Isometry3d>& imu_poses, const std::vector<double>& times, const Eigen::Isometry3d& velo_T_imu)
{
	Trajectory traj;
	for (std::size_t i = 0; i < imu_poses.size() && i < times.size(); ++i)
		traj.push_back({times[i], velo_T_imu * imu_poses[i] * velo_T_imu.inverse()});
	return traj;
}
}  // namespace vlo::io
