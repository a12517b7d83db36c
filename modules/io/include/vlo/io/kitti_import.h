#pragma once
// KITTI -> rawlog importers (vlo-import kitti-odometry / kitti-raw). Vehicle frame = Velodyne frame.
// Both write through RawlogWriter, so a failed import leaves no output behind.
#include <string>
#include <vector>

namespace vlo::io
{
struct ImportSummary
{
	std::size_t frames = 0, images = 0, scans = 0;
	std::size_t invalid_points = 0;  ///< NaN/inf points dropped from the .bin files
	std::vector<std::string> warnings;  ///< one line each, for the user
	std::string rawlog, ground_truth;  ///< written files (ground_truth empty when none)
	/// KITTI raw: the OXTS truth dead-reckoned from its velocities (doc/EVALUATION.md), empty when none
	std::string velocity_truth;
	double seconds = 0;  ///< wall time
};

struct KittiOdometryImport
{
	std::string root;  ///< holds sequences/NN/ and poses/NN.txt
	std::string seq;  ///< "06"
	std::string out;  ///< X.rawlog; ground truth goes to X.gt.tum
	long first = 0, last = -1;  ///< frame range, inclusive; last < 0: to the end
	int camera = -1;  ///< image_<camera> with P<camera>: 0 grey, 2 colour (stored grayscale); -1: 0, else 2 (the first there)
	std::string camera_label = "CAMERA", lidar_label = "LIDAR";
};
ImportSummary importKittiOdometry(const KittiOdometryImport& opt);

struct KittiRawImport
{
	std::string drive;  ///< holds image_0X/data/*.png and velodyne_points/data/*.bin
	std::string calib;  ///< holds calib_cam_to_cam.txt and calib_velo_to_cam.txt
	std::string out;
	int camera = -1;  ///< 0..3 (1 and 3 are the right-hand cameras; colour stored grayscale); -1: 0, else 2 (the first there)
	std::string camera_label = "CAMERA", lidar_label = "LIDAR";
};
ImportSummary importKittiRaw(const KittiRawImport& opt);

/// "X.gt.tum" for "X.rawlog" (any other name gets ".gt.tum" appended).
std::string groundTruthPathFor(const std::string& rawlog_path);
/// "X.gt_velocity.tum" for "X.rawlog" (likewise).
std::string velocityTruthPathFor(const std::string& rawlog_path);
}  // namespace vlo::io
