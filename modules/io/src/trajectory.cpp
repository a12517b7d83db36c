#include "printable.h"

#include <vlo/core/atomic_file.h>
#include <vlo/core/error.h>
#include <vlo/core/input_file.h>
#include <vlo/core/se3.h>
#include <vlo/io/trajectory.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace vlo::io
{
namespace
{
/// Parses exactly n finite numbers from a line or throws naming file and line.
std::vector<double> parseNumbers(const std::string& line, size_t n, const std::string& path, size_t lineNo)
{
	std::istringstream ss(line);
	std::vector<double> v;
	std::string tok;
	while (ss >> tok)
	{
		char* end = nullptr;
		const double d = std::strtod(tok.c_str(), &end);
		if (*end != '\0')
			failInput(path, "line " + std::to_string(lineNo) + ": '" + printable(tok) + "' is not a number");
		if (!std::isfinite(d)) failInput(path, "line " + std::to_string(lineNo) + ": non-finite value");
		v.push_back(d);
	}
	if (v.size() != n)
		failInput(path, "line " + std::to_string(lineNo) + ": expected " + std::to_string(n) + " numbers, found " + std::to_string(v.size()));
	return v;
}

bool skippable(const std::string& line)
{
	const auto p = line.find_first_not_of(" \t\r");
	return p == std::string::npos || line[p] == '#';
}

/// Calls use(numbers, line number) for each line of the text file that is neither blank nor a comment,
/// holding exactly n numbers (else throws naming the file and line).
template <class Use>
void forEachRow(const std::string& path, size_t n, Use&& use)
{
	auto in = openInputFile(path);
	std::string line;
	for (size_t lineNo = 1; std::getline(in, line); ++lineNo)
		if (!skippable(line)) use(parseNumbers(line, n, path, lineNo), lineNo);
}

/// Writes one line per pose with write(stream, pose), 9 significant digits, all or nothing.
template <class Write>
void writeRows(const std::string& path, const Trajectory& traj, Write&& write)
{
	AtomicOutputFile f(path);
	auto& out = f.stream();
	out.precision(9);
	for (const auto& p : traj) write(out, p);
	f.commit();
}
}  // namespace

Trajectory readTum(const std::string& path)
{
	Trajectory traj;
	forEachRow(path, 8, [&](const std::vector<double>& v, size_t lineNo) {
		StampedPose p;
		p.t = v[0];
		if (!traj.empty() && p.t <= traj.back().t)
			failInput(path, "line " + std::to_string(lineNo) + ": timestamp " + std::to_string(p.t) + " is not after the previous one");
		Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
		if (q.norm() < 1e-6) failInput(path, "line " + std::to_string(lineNo) + ": zero quaternion");
		p.pose.linear() = q.normalized().toRotationMatrix();
		p.pose.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
		traj.push_back(p);
	});
	return traj;
}

void writeTum(const std::string& path, const Trajectory& traj)
{
	writeRows(path, traj, [](std::ostream& out, const StampedPose& p) {
		const Eigen::Quaterniond q(p.pose.rotation());
		const Eigen::Vector3d t = p.pose.translation();
		out << std::fixed << p.t << ' ' << t.x() << ' ' << t.y() << ' ' << t.z() << ' ' << q.x() << ' ' << q.y()
			<< ' ' << q.z() << ' ' << q.w() << '\n';
	});
}

TrajectoryFormat trajectoryFormatOf(const std::string& path)
{
	auto in = openInputFile(path);
	std::string line;
	for (size_t lineNo = 1; std::getline(in, line); ++lineNo)
	{
		if (skippable(line)) continue;
		std::istringstream ss(line);
		std::size_t n = 0;
		for (std::string tok; ss >> tok;) ++n;
		if (n == 8) return TrajectoryFormat::Tum;
		if (n == 12) return TrajectoryFormat::Kitti;
		failInput(path,
			"line " + std::to_string(lineNo) + ": " + std::to_string(n) +
				" values, expected 8 (TUM: t x y z qx qy qz qw) or 12 (KITTI poses: row-major 3x4)");
	}
	failInput(path, "no pose (an empty file, or only comments)");
}

std::vector<double> readKittiTimes(const std::string& path)
{
	std::vector<double> times;
	forEachRow(path, 1, [&](const std::vector<double>& v, size_t lineNo) {
		if (!times.empty() && v[0] <= times.back())
			failInput(path, "line " + std::to_string(lineNo) + ": time is not after the previous one");
		times.push_back(v[0]);
	});
	return times;
}

Trajectory readKittiPoses(const std::string& path, const std::vector<double>& times)
{
	Trajectory traj;
	forEachRow(path, 12, [&](const std::vector<double>& v, size_t) {
		StampedPose p;
		Eigen::Matrix3d R;
		for (int r = 0; r < 3; ++r)
		{
			for (int c = 0; c < 3; ++c) R(r, c) = v[4 * r + c];
			p.pose.translation()[r] = v[4 * r + 3];
		}
		p.pose.linear() = orthonormalize(R);
		traj.push_back(p);
	});
	if (!times.empty() && times.size() < traj.size())
		failInput(path, std::to_string(traj.size()) + " poses but only " + std::to_string(times.size()) + " times");
	for (size_t i = 0; i < traj.size(); ++i) traj[i].t = times.empty() ? 0.1 * i : times[i];
	return traj;
}

void writeKittiPoses(const std::string& path, const Trajectory& traj)
{
	writeRows(path, traj, [](std::ostream& out, const StampedPose& p) {
		const Eigen::Matrix4d M = p.pose.matrix();
		for (int r = 0; r < 3; ++r)
			for (int c = 0; c < 4; ++c) out << std::scientific << M(r, c) << ((r == 2 && c == 3) ? '\n' : ' ');
	});
}

Trajectory cameraToVehicle(const Trajectory& cam0, const Eigen::Isometry3d& cam0_T_velo)
{
	Trajectory out = cam0;
	for (auto& p : out) p.pose = cam0_T_velo.inverse() * p.pose * cam0_T_velo;
	return out;
}

Trajectory vehicleToCamera(const Trajectory& vehicle, const Eigen::Isometry3d& cam0_T_velo)
{
	Trajectory out = vehicle;
	for (auto& p : out) p.pose = cam0_T_velo * p.pose * cam0_T_velo.inverse();
	return out;
}
}  // namespace vlo::io
