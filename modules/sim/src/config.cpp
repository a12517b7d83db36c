#include <vlo/core/error.h>
#include <vlo/sim/config.h>

#include <cmath>

namespace vlo::sim
{
Scenario parseScenario(const std::string& name)
{
	if (name == "urban") return Scenario::Urban;
	if (name == "trees") return Scenario::Trees;
	if (name == "corridor") return Scenario::Corridor;
	failInput("--scenario", "unknown scenario '" + name + "' (urban, trees or corridor)");
}

std::string scenarioName(Scenario s)
{
	switch (s)
	{
		case Scenario::Urban: return "urban";
		case Scenario::Trees: return "trees";
		case Scenario::Corridor: return "corridor";
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
	const double deg = M_PI / 180;
	auto rot = [](double yaw, double pitch, double roll) {
		return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
			Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
			.toRotationMatrix();
	};
	// Optical frame (z forward, x right, y down) expressed in vehicle axes (x forward, y left, z up).
	Eigen::Matrix3d optical;
	optical << 0, 0, 1, -1, 0, 0, 0, -1, 0;
	rig.vehicle_T_camera.linear() = rot(0.4 * deg, 0.8 * deg, -0.3 * deg) * optical;
	rig.vehicle_T_camera.translation() = Eigen::Vector3d(1.07, 0.06, 1.65);
	rig.vehicle_T_lidar.linear() = rot(-0.7 * deg, 0.3 * deg, 0.2 * deg);
	rig.vehicle_T_lidar.translation() = Eigen::Vector3d(0.80, 0.0, 1.73);
	return rig;
}
}  // namespace vlo::sim
