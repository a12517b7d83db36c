#include "kitti_import_common.h"

#include <vlo/core/error.h>
#include <vlo/core/stopwatch.h>
#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/kitti_import.h>

#include <filesystem>

namespace vlo
{
namespace fs = std::filesystem;

namespace
{
std::vector<double> timesIfPresent(const std::string& path, long max_index)
{
	if (!fs::exists(path)) return {};
	auto t = readKittiRawTimestamps(path);
	if (static_cast<long>(t.size()) <= max_index)
		failInput(path, "has " + std::to_string(t.size()) + " lines, frame " + std::to_string(max_index) + " has none");
	return t;
}
}  // namespace

ImportSummary importKittiRaw(const KittiRawImport& opt)
{
	const auto start = SteadyClock::now();
	ImportSummary summary;
	summary.rawlog = opt.out;
	if (opt.camera < 0 || opt.camera > 3) failInput("--camera", "must be 0, 1, 2 or 3");
	const std::string X = "0" + std::to_string(opt.camera);
	const auto calib = readKittiRawCalib(
		(fs::path(opt.calib) / "calib_cam_to_cam.txt").string(), (fs::path(opt.calib) / "calib_velo_to_cam.txt").string(),
		opt.camera);
	const std::string cam_dir = (fs::path(opt.drive) / ("image_" + X)).string();
	const std::string velo_dir = (fs::path(opt.drive) / "velodyne_points").string();
	const auto images = listNumberedFiles(cam_dir + "/data", "png");
	const bool lidar = fs::is_directory(velo_dir + "/data");
	if (!lidar) summary.warnings.push_back(velo_dir + "/data: not found, writing a camera-only rawlog");
	const auto scans = lidar ? listNumberedFiles(velo_dir + "/data", "bin") : std::map<long, std::string>{};

	// Each sensor's own timestamps; a sensor without them borrows the other's; neither: 10 Hz from 0.
	const long max_index = std::max(images.rbegin()->first, scans.empty() ? 0L : scans.rbegin()->first);
	auto t_img = timesIfPresent(cam_dir + "/timestamps.txt", images.rbegin()->first);
	auto t_velo = lidar ? timesIfPresent(velo_dir + "/timestamps.txt", scans.rbegin()->first) : std::vector<double>{};
	if (t_img.empty() && t_velo.empty())
	{
		summary.warnings.push_back(opt.drive + ": no timestamps.txt, assuming 10 Hz from t = 0");
		for (long i = 0; i <= max_index; ++i) t_img.push_back(0.1 * i);
	}
	if (t_img.empty()) t_img = t_velo;
	if (t_velo.empty()) t_velo = t_img;

	std::vector<KittiFrameFiles> frames;
	std::size_t missing_scans = 0;
	for (const auto& [index, image] : images)
	{
		KittiFrameFiles f;
		f.index = static_cast<std::size_t>(index);
		f.image = image;
		const auto s = scans.find(index);
		if (s != scans.end()) f.scan = s->second;
		else if (lidar) ++missing_scans;
		// A sensor that borrowed the other's timestamps may have frames beyond them.
		if (f.index >= t_img.size() || (!f.scan.empty() && f.index >= t_velo.size()))
			failInput(opt.drive, "frame " + std::to_string(index) + " has no timestamp (only one sensor has timestamps.txt)");
		f.t_image = t_img[f.index];
		f.t_scan = f.scan.empty() ? f.t_image : t_velo[f.index];
		frames.push_back(f);
	}
	if (missing_scans > 0)
		summary.warnings.push_back(velo_dir + "/data: " + std::to_string(missing_scans) + " frames have no scan");

	SensorRig rig;
	rig.has_camera = true;
	rig.camera = calib.camera_intrinsics;
	rig.vehicle_T_camera = calib.camera_T_velo.inverse();
	rig.has_lidar = lidar;
	writeKittiFrames(frames, rig, calib.cam0_T_velo.inverse(), opt.camera_label, opt.lidar_label, "kitti-raw", summary);
	summary.seconds = msSince(start) / 1000.0;
	return summary;
}
}  // namespace vlo
