#include <vlo/core/error.h>
#include <vlo/core/input_file.h>
#include <vlo/core/se3.h>
#include <vlo/io/kitti_calib.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vlo::io
{
KittiCalibFile::KittiCalibFile(const std::string& path) : path_(path)
{
	auto in = openInputFile(path);
	std::string line;
	for (std::size_t lineNo = 1; std::getline(in, line); ++lineNo)
	{
		const auto colon = line.find(':');
		if (colon == std::string::npos) continue;
		const std::string key = line.substr(0, colon);
		std::istringstream ss(line.substr(colon + 1));
		std::vector<double> v;
		std::string tok;
		bool numeric = true;
		while (ss >> tok)
		{
			char* end = nullptr;
			const double d = std::strtod(tok.c_str(), &end);
			if (*end != '\0') numeric = false;
			v.push_back(d);
		}
		if (numeric)
			values_[key] = v;
		else
			non_numeric_[key] = line;
	}
}

std::vector<double> KittiCalibFile::get(const std::string& key, std::size_t n) const
{
	const auto it = values_.find(key);
	if (it == values_.end())
		failInput(path_, non_numeric_.count(key) ? "key '" + key + "' does not hold numbers" : "missing key '" + key + "'");
	if (it->second.size() != n)
		failInput(path_, "key '" + key + "' has " + std::to_string(it->second.size()) + " numbers, expected " + std::to_string(n));
	for (double d : it->second)
		if (!std::isfinite(d)) failInput(path_, "key '" + key + "' holds a non-finite number");
	return it->second;
}

Matrix34d KittiCalibFile::matrix34(const std::string& key) const
{
	const auto v = get(key, 12);
	Matrix34d M;
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c) M(r, c) = v[4 * r + c];
	return M;
}

Eigen::Matrix3d KittiCalibFile::matrix33(const std::string& key) const
{
	const auto v = get(key, 9);
	Eigen::Matrix3d M;
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c) M(r, c) = v[3 * r + c];
	return M;
}

Eigen::Vector3d KittiCalibFile::vector3(const std::string& key) const
{
	const auto v = get(key, 3);
	return {v[0], v[1], v[2]};
}

PinholeCamera intrinsicsOf(const Matrix34d& P, int width, int height)
{
	PinholeCamera c;
	c.fx = P(0, 0);
	c.fy = P(1, 1);
	c.cx = P(0, 2);
	c.cy = P(1, 2);
	c.width = width;
	c.height = height;
	return c;
}

Eigen::Vector3d offsetOf(const Matrix34d& P) { return P.leftCols<3>().inverse() * P.col(3); }

Eigen::Isometry3d rigidFrom34(const Matrix34d& M)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = orthonormalize(M.leftCols<3>());
	T.translation() = M.col(3);
	return T;
}

Eigen::Isometry3d rigidFromRowMajor(const std::vector<double>& v, const std::string& where)
{
	if (v.size() != 12) failInput(where, "expected 12 numbers (row-major 3x4), found " + std::to_string(v.size()));
	Matrix34d M;
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c) M(r, c) = v[4 * r + c];
	// Calibration files print ~10 digits: accept that rounding, reject anything that is no rotation.
	const Eigen::Matrix3d R = M.leftCols<3>();
	if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-3 || R.determinant() < 0)
		failInput(where, "the 3x3 part is not a rotation matrix");
	return rigidFrom34(M);
}

Eigen::Isometry3d rigidFromText(const std::string& text, const std::string& where)
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
	return rigidFromRowMajor(v, where);
}

Eigen::Isometry3d nominalCam0TVehicle()
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
	return T;
}

namespace
{
/// A rectified projection as KITTI prints it, K [I | t] with last row 0 0 1 t_z and pixel-sized
/// numbers: anything else (a singular, skewed or absurd matrix) comes from a corrupt file.
void checkProjection(const Matrix34d& P, const std::string& path, const std::string& key)
{
	const bool shape = std::abs(P(1, 0)) < 1e-6 && std::abs(P(2, 0)) < 1e-6 && std::abs(P(2, 1)) < 1e-6 &&
		std::abs(P(2, 2) - 1) < 1e-6;
	if (!shape || P.cwiseAbs().maxCoeff() >= 1e6 || !offsetOf(P).allFinite())
		failInput(path, key + " is not a rectified projection K [I | t] (last row 0 0 1 t_z, values below 1e6)");
}

/// [R | t] whose R is a rotation up to the printed digits; anything else comes from a corrupt file.
Eigen::Isometry3d rigidOrFail(const Matrix34d& M, const std::string& path, const std::string& key)
{
	const Eigen::Matrix3d R = M.leftCols<3>();
	if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-3 || R.determinant() <= 0 ||
		M.col(3).norm() >= 1e6)
		failInput(path, key + " is not a rigid transform [R | t] (R must be a rotation, t below 1e6)");
	return rigidFrom34(M);
}
}  // namespace

KittiOdometryCalib readKittiOdometryCalib(const std::string& calib_txt, int camera)
{
	const KittiCalibFile f(calib_txt);
	KittiOdometryCalib c;
	c.P0 = f.matrix34("P0");
	if (c.P0(0, 0) <= 0 || c.P0(1, 1) <= 0) failInput(calib_txt, "P0 has a non-positive focal length");
	checkProjection(c.P0, calib_txt, "P0");
	if (camera < 0 || camera > 3) failInput(calib_txt, "camera " + std::to_string(camera) + " does not exist (0..3)");
	const std::string Pc = "P" + std::to_string(camera);
	c.camera = camera;
	c.P = f.matrix34(Pc);
	if (c.P(0, 0) <= 0 || c.P(1, 1) <= 0) failInput(calib_txt, Pc + " has a non-positive focal length");
	checkProjection(c.P, calib_txt, Pc);
	c.has_tr = f.has("Tr");
	c.cam0_T_velo = c.has_tr ? rigidOrFail(f.matrix34("Tr"), calib_txt, "Tr") : nominalCam0TVehicle();
	return c;
}

KittiRawCalib readKittiRawCalib(const std::string& cam_to_cam, const std::string& velo_to_cam, int camera)
{
	const KittiCalibFile cc(cam_to_cam), vc(velo_to_cam);
	KittiRawCalib c;
	c.camera = camera;
	const std::string X = "0" + std::to_string(camera);
	c.P_rect = cc.matrix34("P_rect_" + X);
	c.R_rect_00 = cc.matrix33("R_rect_00");
	const auto S = cc.get("S_rect_" + X, 2);
	for (const double side : S)  // checked before the cast: a double beyond int's range has no int value
		if (!(side >= 1 && side <= 1e5) || side != std::floor(side))
			failInput(cam_to_cam, "S_rect_" + X + " is not an image size (two whole numbers of pixels)");
	c.camera_intrinsics = intrinsicsOf(c.P_rect, static_cast<int>(S[0]), static_cast<int>(S[1]));
	if (!c.camera_intrinsics.valid()) failInput(cam_to_cam, "P_rect_" + X + " or S_rect_" + X + " is not a valid camera");
	checkProjection(c.P_rect, cam_to_cam, "P_rect_" + X);
	Matrix34d R_rect = Matrix34d::Zero();
	R_rect.leftCols<3>() = c.R_rect_00;
	rigidOrFail(R_rect, cam_to_cam, "R_rect_00");
	c.velo_to_cam.leftCols<3>() = vc.matrix33("R");
	c.velo_to_cam.col(3) = vc.vector3("T");
	rigidOrFail(c.velo_to_cam, velo_to_cam, "R, T");
	// camera X <- rectified cam0 (offset t) <- unrectified cam0 (R_rect_00) <- Velodyne ([R|T]).
	Matrix34d cam0_T_velo;
	cam0_T_velo.leftCols<3>() = c.R_rect_00 * c.velo_to_cam.leftCols<3>();
	cam0_T_velo.col(3) = c.R_rect_00 * c.velo_to_cam.col(3);
	Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
	offset.translation() = offsetOf(c.P_rect);
	c.cam0_T_velo = rigidFrom34(cam0_T_velo);
	c.camera_T_velo = offset * c.cam0_T_velo;
	return c;
}

Matrix34d KittiRawCalib::projection() const
{
	Eigen::Matrix4d R4 = Eigen::Matrix4d::Identity(), T4 = Eigen::Matrix4d::Identity();
	R4.topLeftCorner<3, 3>() = R_rect_00;
	T4.topRows<3>() = velo_to_cam;
	return P_rect * R4 * T4;
}

Eigen::Isometry3d readKittiImuToVelo(const std::string& imu_to_velo)
{
	const KittiCalibFile f(imu_to_velo);
	Matrix34d M;
	M << f.matrix33("R"), f.vector3("T");
	return rigidOrFail(M, imu_to_velo, "R, T");
}
}  // namespace vlo::io
