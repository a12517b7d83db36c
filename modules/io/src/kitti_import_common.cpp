#include "kitti_import_common.h"

#include <vlo/core/error.h>
#include <vlo/core/progress.h>
#include <vlo/core/stderr_capture.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/rawlog_writer.h>

#include <cctype>
#include <filesystem>

namespace vlo::io
{
namespace fs = std::filesystem;

namespace
{
std::string besideRawlog(const std::string& rawlog_path, const std::string& suffix)
{
	const std::string ext = ".rawlog";
	if (rawlog_path.size() > ext.size() && rawlog_path.compare(rawlog_path.size() - ext.size(), ext.size(), ext) == 0)
		return rawlog_path.substr(0, rawlog_path.size() - ext.size()) + suffix;
	return rawlog_path + suffix;
}
}  // namespace

std::string groundTruthPathFor(const std::string& rawlog_path) { return besideRawlog(rawlog_path, ".gt.tum"); }
std::string velocityTruthPathFor(const std::string& rawlog_path) { return besideRawlog(rawlog_path, ".gt_velocity.tum"); }

int chooseCamera(int camera, const std::string& prefix)
{
	if (camera != -1) return camera;
	for (int c : {0, 2, 1, 3})
		if (fs::is_directory(prefix + std::to_string(c))) return c;
	return 0;
}

std::map<long, std::string> listNumberedFiles(const std::string& dir, const std::string& ext)
{
	std::error_code ec;
	if (!fs::is_directory(dir, ec)) failInput(dir, "directory not found");
	std::map<long, std::string> files;
	for (const auto& e : fs::directory_iterator(dir, ec))
	{
		const std::string stem = e.path().stem().string();
		if (e.path().extension() != "." + ext || stem.empty()) continue;
		bool digits = true;
		for (char c : stem) digits = digits && std::isdigit(static_cast<unsigned char>(c));
		if (digits) files[std::stol(stem)] = e.path().string();
	}
	if (files.empty()) failInput(dir, "no numbered ." + ext + " files");
	return files;
}

void writeKittiFrames(const std::vector<KittiFrameFiles>& frames, SensorRig rig,
	const Eigen::Isometry3d& vehicle_T_camera0, const std::string& camera_label,
	const std::string& lidar_label, const std::string& progress_label, ImportSummary& summary)
{
	RawlogWriter writer(summary.rawlog);
	if (!frames.empty()) writer.noteCamera0(vehicle_T_camera0, frames.front().t_image);
	ProgressLine progress(progress_label, frames.size());
	std::size_t scans_with_invalid = 0;
	std::string first_invalid;
	for (const auto& files : frames)
	{
		if (!files.image.empty())
		{
			Frame f;
			f.index = files.index;
			f.t = files.t_image;
			StderrCapture capture;  // libpng says why before the load fails
			if (!f.image.loadFromFile(files.image, 0)) failInput(files.image, withReason("cannot read image", capture.taken()));
			const int w = static_cast<int>(f.image.getWidth()), h = static_cast<int>(f.image.getHeight());
			if (rig.camera.width == 0) rig.camera.width = w, rig.camera.height = h;
			if (w != rig.camera.width || h != rig.camera.height)
				failInput(files.image,
					"image is " + std::to_string(w) + "x" + std::to_string(h) + ", expected " +
						std::to_string(rig.camera.width) + "x" + std::to_string(rig.camera.height) +
						" (calibration or first image)");
			f.has_image = true;
			f.rig = rig;
			writer.writeFrame(f, camera_label, lidar_label);
			++summary.images;
		}
		if (!files.scan.empty())
		{
			Frame s;
			s.index = files.index;
			s.t = files.t_scan;
			const std::size_t dropped = readKittiBin(files.scan, s.scan);
			// Single NaN returns are dropped with a warning; a scan with no valid point is corrupt.
			if (s.scan.empty())
				failInput(files.scan, dropped > 0 ? "every point is NaN or infinite" : "empty scan (no point)");
			if (dropped > 0 && scans_with_invalid++ == 0) first_invalid = files.scan;
			if (files.motion_compensated)
			{
				for (LidarPoint& p : s.scan) p.time = 0.0f;
				s.scan.has_time = true;
			}
			else if (files.sweep)
				setTimesFromAzimuth(s.scan, *files.sweep);
			if (s.scan.has_time)
				for (LidarPoint& p : s.scan) p.intensity *= 255.0f;
			summary.invalid_points += dropped;
			s.has_scan = true;
			s.rig = rig;
			writer.writeFrame(s, camera_label, lidar_label);
			++summary.scans;
		}
		progress.update(++summary.frames);
	}
	writer.commit();
	progress.finish();
	if (scans_with_invalid > 0)
		summary.warnings.push_back(first_invalid + ": " + std::to_string(summary.invalid_points) +
			" non-finite points dropped from " + std::to_string(scans_with_invalid) + " scans (this is the first)");
}
}  // namespace vlo::io
