#include <vlo/core/error.h>
#include <vlo/eval/camera_frame.h>
#include <vlo/io/kitti_calib.h>

namespace vlo::eval
{
Eigen::Isometry3d parseCam0TVehicle(const std::string& text, const std::string& where)
{
	return io::rigidFromText(text, where);
}

Eigen::Isometry3d readKittiCalibTr(const std::string& path)
{
	// Unlike the importer, no nominal fallback: a metric in the wrong frame would pass unnoticed.
	return io::rigidFromRowMajor(io::KittiCalibFile(path).get("Tr", 12), path + ": Tr");
}
}  // namespace vlo::eval
