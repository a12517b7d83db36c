#include <vlo/core/error.h>
#include <vlo/rosbag/extrinsics_file.h>
#include <vlo/rosbag/yaml_file.h>

#include <mrpt/containers/yaml.h>

#include <cmath>

namespace vlo::rosbag_io
{
Eigen::Isometry3d readExtrinsicsFile(const std::string& path)
{
	const std::string format = "expected 'lidar_T_camera: [16 numbers]' (row-major 4x4, camera optical frame in LiDAR frame)";
	Eigen::Matrix4d M;
	try
	{
		const auto doc = readYamlFile(path);
		if (!doc.isMap() || !doc.has("lidar_T_camera")) failInput(path, "no key lidar_T_camera; " + format);
		const auto& seq = doc["lidar_T_camera"];
		if (!seq.isSequence() || seq.asSequence().size() != 16) failInput(path, "lidar_T_camera: " + format);
		for (int i = 0; i < 16; ++i) M(i / 4, i % 4) = seq.asSequence()[i].as<double>();
	}
	catch (const InputError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		failInput(path, "not readable as YAML with " + format);
	}
	if (!M.allFinite()) failInput(path, "lidar_T_camera has a non-finite number");
	if (!M.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1), 1e-12)) failInput(path, "lidar_T_camera: last row is not 0 0 0 1");
	const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
	if ((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6 || R.determinant() < 0)
		failInput(path, "lidar_T_camera: the rotation is not orthonormal");
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::Quaterniond(R).normalized().toRotationMatrix();  // onto SO(3): files print ~15 digits
	T.translation() = M.topRightCorner<3, 1>();
	return T;
}
}  // namespace vlo::rosbag_io
