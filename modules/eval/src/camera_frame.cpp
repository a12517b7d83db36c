#include <vlo/core/error.h>
#include <vlo/core/se3.h>
#include <vlo/eval/camera_frame.h>
#include <vlo/io/kitti_calib.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace vlo
{
namespace
{
Eigen::Isometry3d rigFrom12(const std::vector<double>& v, const std::string& where)
{
	if (v.size() != 12) failInput(where, "expected 12 numbers (row-major 3x4), found " + std::to_string(v.size()));
	Eigen::Matrix3d R;
	Eigen::Vector3d p;
	for (int r = 0; r < 3; ++r)
	{
		for (int c = 0; c < 3; ++c) R(r, c) = v[4 * r + c];
		p(r) = v[4 * r + 3];
	}
	// Calibration files print ~10 digits: accept that rounding, reject anything that is no rotation.
	if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-3 || R.determinant() < 0)
		failInput(where, "the 3x3 part is not a rotation matrix");
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = orthonormalize(R);
	T.translation() = p;
	return T;
}
}  // namespace

Eigen::Isometry3d parseCam0TVehicle(const std::string& text, const std::string& where)
{
	std::string t = text;
	for (char& c : t)
		if (c == ',') c = ' ';
	std::istringstream ss(t);
	std::vector<double> v;
	for (std::string tok; ss >> tok;)
	{
		char* end = nullptr;
		const double d = std::strtod(tok.c_str(), &end);
		if (*end != '\0' || !std::isfinite(d)) failInput(where, "'" + tok + "' is not a finite number");
		v.push_back(d);
	}
	return rigFrom12(v, where);
}

Eigen::Isometry3d readKittiCalibTr(const std::string& path)
{
	// Unlike the importer, no nominal fallback: a metric in the wrong frame would pass unnoticed.
	return rigFrom12(KittiCalibFile(path).get("Tr", 12), path + ": Tr");
}
}  // namespace vlo
