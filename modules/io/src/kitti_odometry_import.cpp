#include "kitti_import_common.h"

#include <vlo/core/error.h>
#include <vlo/core/stopwatch.h>
#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/trajectory.h>

#include <filesystem>

namespace vlo::io
{
namespace fs = std::filesystem;

namespace
{
/// Ground truth of the selected frames in the vehicle frame, relative to the first of them.
Trajectory groundTruth(const std::string& poses, const std::vector<double>& times,
	const std::vector<KittiFrameFiles>& frames, const Eigen::Isometry3d& cam0_T_velo)
{
	const Trajectory all = readKittiPoses(poses, times);
	Trajectory sel;
	for (const auto& f : frames)
	{
		if (f.index >= all.size())
			failInput(poses, "has " + std::to_string(all.size()) + " poses, frame " + std::to_string(f.index) + " has none");
		sel.push_back(all[f.index]);
	}
	return relativeToFirst(cameraToVehicle(sel, cam0_T_velo));
}
}  // namespace

ImportSummary importKittiOdometry(const KittiOdometryImport& opt)
{
	const auto start = SteadyClock::now();
	ImportSummary summary;
	summary.rawlog = opt.out;
	const std::string seq = (fs::path(opt.root) / "sequences" / opt.seq).string();
	const std::string calib_path = seq + "/calib.txt", times_path = seq + "/times.txt";
	const int camera = chooseCamera(opt.camera, seq + "/image_");
	const auto calib = readKittiOdometryCalib(calib_path, camera);
	const std::string image_dir = seq + "/image_" + std::to_string(camera);
	for (int other = 0; other < 4 && !fs::is_directory(image_dir); ++other)  // e.g. colour-only downloads
		if (fs::is_directory(seq + "/image_" + std::to_string(other)))
			failInput(image_dir,
				"directory not found (this sequence has image_" + std::to_string(other) +
					": give --camera " + std::to_string(other) + ")");
	const auto images = listNumberedFiles(image_dir, "png");
	const auto times = readKittiTimes(times_path);

	const bool has_velodyne = fs::is_directory(seq + "/velodyne");
	const bool lidar = has_velodyne && calib.has_tr;
	if (!has_velodyne) summary.warnings.push_back(seq + ": no velodyne/ folder, writing a camera-only rawlog");
	if (has_velodyne && !calib.has_tr)
		summary.warnings.push_back(calib_path + ": no Tr (Velodyne to camera), writing a camera-only rawlog");
	if (!calib.has_tr)
		summary.warnings.push_back(calib_path +
			": without Tr the vehicle frame is camera 0 turned to x forward, y left, z up (also for the ground truth)");
	const auto scans = lidar ? listNumberedFiles(seq + "/velodyne", "bin") : std::map<long, std::string>{};

	// Every frame from the first to the last with a file: one without its image (or scan) is said, not dropped.
	const long first_file = std::min(images.begin()->first, scans.empty() ? images.begin()->first : scans.begin()->first);
	const long last_file = std::max(images.rbegin()->first, scans.empty() ? 0L : scans.rbegin()->first);
	const long last = opt.last < 0 ? last_file : opt.last;
	if (opt.first < 0 || opt.first > last)
		failInput("command line", "bad frame range --first " + std::to_string(opt.first) + " --last " + std::to_string(last));
	if (opt.last > last_file)
		summary.warnings.push_back("--last " + std::to_string(opt.last) + ": " + seq + " ends at frame " +
			std::to_string(last_file) + ", importing up to it");
	std::vector<KittiFrameFiles> frames;
	std::vector<long> missing_images, missing_scans;
	for (long i = std::max(opt.first, first_file); i <= std::min(last, last_file); ++i)
	{
		const auto image = images.find(i);
		const auto scan = scans.find(i);
		if (image == images.end()) missing_images.push_back(i);
		if (lidar && scan == scans.end()) missing_scans.push_back(i);
		if (image == images.end() && scan == scans.end()) continue;
		KittiFrameFiles f;
		f.index = static_cast<std::size_t>(i);
		if (f.index >= times.size())
			failInput(times_path,
				"has " + std::to_string(times.size()) + " times, " +
					(image != images.end() ? "image " + image->second : "scan " + scan->second) +
					" has none");
		f.t_image = f.t_scan = times[f.index];
		if (image != images.end()) f.image = image->second;
		if (scan != scans.end()) f.scan = scan->second;
		frames.push_back(f);
	}
	const auto noteMissing = [&](const std::vector<long>& missing, const std::string& dir, const std::string& what,
								 const std::string& consequence) {
		if (!missing.empty())
			summary.warnings.push_back(dir + ": no " + what + " for " + std::to_string(missing.size()) +
				(missing.size() == 1 ? " frame" : " frames") + " (the first: frame " + std::to_string(missing.front()) +
				"); " + consequence);
	};
	noteMissing(missing_images, image_dir, "image",
		lidar ? "their scans are imported without one, frames with neither are skipped" : "they are skipped");
	noteMissing(missing_scans, seq + "/velodyne", "scan", "their images are imported without one");
	if (frames.empty()) failInput(image_dir, "no images in the frame range " + std::to_string(opt.first) + ".." + std::to_string(last));

	// Read the ground truth before writing anything, so that a bad poses file leaves no output.
	const std::string poses = (fs::path(opt.root) / "poses" / (opt.seq + ".txt")).string();
	Trajectory gt;
	if (fs::exists(poses))
		gt = groundTruth(poses, times, frames, calib.cam0_T_velo);
	else
		summary.warnings.push_back(poses + ": not found, no ground truth written");

	SensorRig rig;
	rig.has_camera = true;
	rig.camera = intrinsicsOf(calib.P, 0, 0);  // size from the first image
	Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();  // camera X's centre from camera 0's
	offset.translation() = offsetOf(calib.P);
	rig.vehicle_T_camera = (offset * calib.cam0_T_velo).inverse();
	rig.has_lidar = lidar;
	writeKittiFrames(frames, rig, calib.cam0_T_velo.inverse(), opt.camera_label, opt.lidar_label, "kitti-odometry " + opt.seq, summary);
	if (!gt.empty())
	{
		summary.ground_truth = groundTruthPathFor(opt.out);
		writeTum(summary.ground_truth, gt);
	}
	summary.seconds = msSince(start) / 1000.0;
	return summary;
}
}  // namespace vlo::io
