#include <vlo/core/error.h>
#include <vlo/rosbag/camera_info.h>
#include <vlo/rosbag/yaml_file.h>

#include <mrpt/containers/yaml.h>

namespace vlo::rosbag_io
{
namespace
{
/// The numbers of a {rows, cols, data} matrix, `n` of them.
std::vector<double> matrixData(const mrpt::containers::yaml& doc, const char* key, std::size_t n, const std::string& path)
{
	if (!doc.has(key)) failInput(path, std::string("no key ") + key);
	const auto& m = doc[key];
	if (!m.isMap() || !m.has("data") || !m["data"].isSequence())
		failInput(path, std::string(key) + ": expected {rows: R, cols: C, data: [...]}");
	std::vector<double> v;
	for (const auto& x : m["data"].asSequence()) v.push_back(x.as<double>());
	if (n > 0 && v.size() != n)
		failInput(path, std::string(key) + ": " + std::to_string(v.size()) + " numbers, expected " + std::to_string(n));
	return v;
}
}  // namespace

sensor_msgs::CameraInfo readCameraInfoFile(const std::string& path)
{
	sensor_msgs::CameraInfo ci;
	try
	{
		const auto doc = readYamlFile(path);
		if (!doc.isMap()) failInput(path, "not a camera calibration YAML (image_width, camera_matrix, ...)");
		for (const char* key : {"image_width", "image_height", "distortion_model"})
			if (!doc.has(key)) failInput(path, std::string("no key ") + key);
		ci.width = doc["image_width"].as<uint32_t>();
		ci.height = doc["image_height"].as<uint32_t>();
		ci.distortion_model = doc["distortion_model"].as<std::string>();
		const auto K = matrixData(doc, "camera_matrix", 9, path);
		std::copy(K.begin(), K.end(), ci.K.begin());
		ci.D = matrixData(doc, "distortion_coefficients", 0, path);
		if (doc.has("projection_matrix"))
		{
			const auto P = matrixData(doc, "projection_matrix", 12, path);
			std::copy(P.begin(), P.end(), ci.P.begin());
		}
	}
	catch (const InputError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		failInput(path, "not readable as a camera calibration YAML (image_width, camera_matrix, ...)");
	}
	return ci;
}
}  // namespace vlo::rosbag_io
