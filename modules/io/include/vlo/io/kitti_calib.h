#pragma once
// KITTI calibration files ("KEY: v1 v2 ..." per line) and the rig they imply.
//  odometry  sequences/NN/calib.txt: P0..P3 (3x4 rectified projections), Tr (velo -> cam0, 3x4)
//  raw       calib_cam_to_cam.txt: P_rect_0X, R_rect_00, S_rect_0X;  calib_velo_to_cam.txt: R, T;
//            calib_imu_to_velo.txt: R, T
#include <vlo/core/frame.h>

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

namespace vlo::io
{
using Matrix34d = Eigen::Matrix<double, 3, 4>;

class KittiCalibFile
{
   public:
	/// Throws InputError naming the file if it is missing or a line has a non-number after a key
	/// whose other values are numbers.
	explicit KittiCalibFile(const std::string& path);
	bool has(const std::string& key) const { return values_.count(key) > 0; }
	/// Exactly n numbers, or InputError naming the file and the missing or malformed key.
	std::vector<double> get(const std::string& key, std::size_t n) const;
	Matrix34d matrix34(const std::string& key) const;
	Eigen::Matrix3d matrix33(const std::string& key) const;
	Eigen::Vector3d vector3(const std::string& key) const;
	const std::string& path() const { return path_; }

   private:
	std::string path_;
	std::map<std::string, std::vector<double>> values_;
	std::map<std::string, std::string> non_numeric_;  // e.g. calib_time: dates are not numbers
};

/// A rectified projection P = K [I | t]: K gives the intrinsics and t = K^-1 P(:,3) is the offset
/// of this camera's frame from the reference rectified frame (x_cam = x_ref + t).
PinholeCamera intrinsicsOf(const Matrix34d& P, int width, int height);
Eigen::Vector3d offsetOf(const Matrix34d& P);

/// Rigid transform from a 3x4 [R|t] whose R is only nearly orthonormal (6 printed digits).
Eigen::Isometry3d rigidFrom34(const Matrix34d& M);
/// The same from 12 numbers, row-major. Throws InputError naming `where` for another count or when the
/// 3x3 part is no rotation (beyond the rounding of ~10 printed digits).
Eigen::Isometry3d rigidFromRowMajor(const std::vector<double>& v, const std::string& where);
/// The same from text: 12 numbers separated by spaces or commas.
Eigen::Isometry3d rigidFromText(const std::string& text, const std::string& where);

/// Used when calib.txt has no Tr: a vehicle frame with axes x forward, y left, z up at camera 0
/// (camera x right, y down, z forward), i.e. cam0_T_vehicle with zero translation.
Eigen::Isometry3d nominalCam0TVehicle();

struct KittiOdometryCalib
{
	Matrix34d P0 = Matrix34d::Zero();
	int camera = 0;  ///< which rectified camera P is (0, 1 grey; 2, 3 colour)
	Matrix34d P = Matrix34d::Zero();  ///< P<camera>: K [I | t] with t the offset from camera 0
	bool has_tr = false;
	Eigen::Isometry3d cam0_T_velo = Eigen::Isometry3d::Identity();  ///< Tr, or nominal if missing
};
KittiOdometryCalib readKittiOdometryCalib(const std::string& calib_txt, int camera = 0);

struct KittiRawCalib
{
	int camera = 0;
	Matrix34d P_rect = Matrix34d::Zero();  ///< P_rect_0X
	Eigen::Matrix3d R_rect_00 = Eigen::Matrix3d::Identity();
	Matrix34d velo_to_cam = Matrix34d::Zero();  ///< [R | T] of calib_velo_to_cam.txt, as printed
	PinholeCamera camera_intrinsics;  ///< from P_rect_0X and S_rect_0X
	Eigen::Isometry3d camera_T_velo = Eigen::Isometry3d::Identity();  ///< rectified camera X <- Velodyne
	Eigen::Isometry3d cam0_T_velo = Eigen::Isometry3d::Identity();  ///< rectified camera 0 <- Velodyne

	/// P_rect_0X * R_rect_00 * [R|T], straight from the file values (the reference projection).
	Matrix34d projection() const;
};
KittiRawCalib readKittiRawCalib(const std::string& cam_to_cam, const std::string& velo_to_cam, int camera);

/// calib_imu_to_velo.txt's R, T: velo_T_imu (x_velo = R x_imu + T).
Eigen::Isometry3d readKittiImuToVelo(const std::string& imu_to_velo);
}  // namespace vlo::io
