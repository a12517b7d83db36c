#include <vlo/core/error.h>
#include <vlo/core/units.h>
#include <vlo/sim/config.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace vlo::sim
{
Scenario parseScenario(const std::string& name)
{
	if (name == "urban") return Scenario::Urban;
	if (name == "trees") return Scenario::Trees;
	if (name == "corridor") return Scenario::Corridor;
	if (name == "loop") return Scenario::Loop;
	if (name == "facades") return Scenario::Facades;
	if (name == "avenue") return Scenario::Avenue;
	if (name == "residential") return Scenario::Residential;
	failInput(
		"--scenario", "unknown scenario '" + name + "' (urban, trees, corridor, loop, facades, avenue or residential)");
}

std::string scenarioName(Scenario s)
{
	switch (s)
	{
		case Scenario::Urban: return "urban";
		case Scenario::Trees: return "trees";
		case Scenario::Corridor: return "corridor";
		case Scenario::Loop: return "loop";
		case Scenario::Facades: return "facades";
		case Scenario::Avenue: return "avenue";
		case Scenario::Residential: return "residential";
	}
	return "?";
}

LidarModel hdl64()
{
	LidarModel m;
	m.name = "hdl64";
	// Upper block: 32 lasers +2 .. -8.33 deg; lower block: 32 lasers -8.83 .. -24.8 deg.
	for (int i = 0; i < 32; ++i) m.elevations_deg.push_back(2.0 - i * (10.33 / 31));
	for (int i = 0; i < 32; ++i) m.elevations_deg.push_back(-8.83 - i * ((24.8 - 8.83) / 31));
	m.azimuth_steps = 2083;  // 0.1728 deg
	m.max_range = 100.0;
	return m;
}

LidarModel vlp16()
{
	LidarModel m;
	m.name = "vlp16";
	for (int i = 0; i < 16; ++i) m.elevations_deg.push_back(15.0 - 2.0 * i);
	m.azimuth_steps = 1800;  // 0.2 deg
	m.max_range = 100.0;
	return m;
}

LidarModel lidarByName(const std::string& name)
{
	if (name == "hdl64") return hdl64();
	if (name == "vlp16") return vlp16();
	failInput("--lidar", "unknown LiDAR '" + name + "' (hdl64 or vlp16)");
}

SensorRig defaultRig()
{
	SensorRig rig;
	rig.has_camera = rig.has_lidar = true;
	rig.camera.fx = rig.camera.fy = 718.856;
	rig.camera.cx = 607.1928;
	rig.camera.cy = 185.2157;
	rig.camera.width = 1241;
	rig.camera.height = 376;
	auto rot = [](double yaw, double pitch, double roll) {
		return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
			Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
			.toRotationMatrix();
	};
	// Optical frame (z forward, x right, y down) expressed in vehicle axes (x forward, y left, z up).
	Eigen::Matrix3d optical;
	optical << 0, 0, 1, -1, 0, 0, 0, -1, 0;
	rig.vehicle_T_camera.linear() = rot(0.4 * kRadPerDeg, 0.8 * kRadPerDeg, -0.3 * kRadPerDeg) * optical;
	rig.vehicle_T_camera.translation() = Eigen::Vector3d(1.07, 0.06, 1.65);
	rig.vehicle_T_lidar.linear() = rot(-0.7 * kRadPerDeg, 0.3 * kRadPerDeg, 0.2 * kRadPerDeg);
	rig.vehicle_T_lidar.translation() = Eigen::Vector3d(0.80, 0.0, 1.73);
	return rig;
}
void setLens(PinholeCamera& camera, const std::string& coefficients, bool fisheye)
{
	const std::string where = "--camera-distortion " + coefficients;
	std::vector<double> k;
	std::stringstream in(coefficients);
	for (std::string item; std::getline(in, item, ',');)
	{
		char* end = nullptr;
		const double v = std::strtod(item.c_str(), &end);
		if (item.empty() || *end != '\0' || !std::isfinite(v) || std::abs(v) > 10) failInput(where, "'" + item + "' is not a coefficient");
		k.push_back(v);
	}
	camera.dist.fill(0.0);
	if (fisheye)
	{
		if (k.size() != 4) failInput(where, "a fisheye (equidistant) lens takes 4 coefficients K1,K2,K3,K4");
		camera.distortion = mrpt::img::DistortionModel::kannala_brandt;
		camera.dist[0] = k[0], camera.dist[1] = k[1], camera.dist[4] = k[2], camera.dist[5] = k[3];
		return;
	}
	if (k.size() != 4 && k.size() != 5) failInput(where, "a plumb_bob lens takes 4 or 5 coefficients K1,K2,P1,P2[,K3]");
	camera.distortion = mrpt::img::DistortionModel::plumb_bob;
	std::copy(k.begin(), k.end(), camera.dist.begin());
}
}  // namespace vlo::sim
