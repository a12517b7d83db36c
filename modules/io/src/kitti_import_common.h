#pragma once
// What both KITTI importers share: numbered data files, and writing frames to a rawlog.
#include <vlo/core/frame.h>
#include <vlo/core/sweep_times.h>
#include <vlo/io/kitti_import.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vlo::io
{
/// `camera` when it is 0..3; for -1 (the importers' default) the first of cameras 0 (grey), 2 (colour),
/// 1 and 3 whose folder `<prefix><X>` exists, else 0 (whose folder's absence is then the error).
int chooseCamera(int camera, const std::string& prefix);

/// Files named "<number>.<ext>" in dir, by number. Throws InputError naming dir if it is missing
/// or holds no such file.
std::map<long, std::string> listNumberedFiles(const std::string& dir, const std::string& ext);

/// The data of one KITTI frame. An empty `image` or `scan` means no image or LiDAR for that frame.
struct KittiFrameFiles
{
	std::size_t index = 0;
	double t_image = 0, t_scan = 0;
	std::string image, scan;
	/// KITTI odometry's scans are motion-compensated: every point is written at the scan's time (0).
	/// A raw sweep is written with times from its azimuth and `sweep` when the recording has the
	/// sweep's stamps, else without times.
	bool motion_compensated = true;
	std::optional<SpinningSweep> sweep;
};

/// Writes the note of KITTI's camera 0 (RawlogWriter::noteCamera0), then the frames (image, then scan, each at
/// its own time) to summary.rawlog through a RawlogWriter, with a progress line. Scans with times are
/// written as Velodyne scans, whose intensity is 8-bit: KITTI's reflectance in [0, 1] goes in as 0-255.
/// A rig camera of size 0 takes the first image's size;
/// every image must have the rig camera's size. Fills the counts of `summary`.
void writeKittiFrames(const std::vector<KittiFrameFiles>& frames, SensorRig rig,
	const Eigen::Isometry3d& vehicle_T_camera0, const std::string& camera_label,
	const std::string& lidar_label, const std::string& progress_label, ImportSummary& summary);
}  // namespace vlo::io
