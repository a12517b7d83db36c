#include "kitti_import_common.h"

#include <vlo/core/error.h>
#include <vlo/core/stopwatch.h>
#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/kitti_oxts.h>
#include <vlo/io/trajectory.h>

#include <cstdio>
#include <filesystem>

namespace vlo::io
{
namespace fs = std::filesystem;

namespace
{
// The HDL-64E of KITTI turns clockwise seen from above (its azimuth falls with time): measured on
// drive 2011_09_26_0013, where the other direction doubles the sweep's distortion (doc/LOAM.md).
constexpr bool kKittiLaserClockwise = true;

std::vector<double> timesIfPresent(const std::string& path, long max_index)
{
	if (!fs::exists(path)) return {};
	auto t = readKittiRawTimestamps(path);
	if (static_cast<long>(t.size()) <= max_index)
		failInput(path,
			"has " + std::to_string(t.size()) + " lines: frames " + std::to_string(t.size()) + " to " +
				std::to_string(max_index) + " have no time");
	return t;
}

/// The sweep of scan `index` from the recording: it turned from t_start to t_end, and the scan's time
/// (velodyne_points/timestamps.txt) is when it faced forward, where it triggered the cameras (KITTI's
/// raw-data readme).
SpinningSweep sweepOf(std::size_t index, double t_scan, const std::vector<double>& start, const std::vector<double>& end,
	const std::string& velo_dir)
{
	const double period = end[index] - start[index], fraction = (t_scan - start[index]) / period;
	if (!(period > 0.01 && period < 1.0) || !(fraction >= 0 && fraction <= 1))
		failInput(velo_dir + "/timestamps_start.txt",
			"frame " + std::to_string(index) +
				": the sweep's start, end and time (timestamps_start, timestamps_end, timestamps) are not in order within 1 s");
	return SpinningSweep{kKittiLaserClockwise, period, 0.0, fraction};
}

/// OXTS ground truth of the frames (oxts/data/<index>.txt at oxts/timestamps.txt's times) in the
/// Velodyne frame, from the positions and dead-reckoned from the velocities; empty, with a warning,
/// when the drive or the calibration lacks what it needs.
struct OxtsTruth
{
	Trajectory positions, velocities;
};
OxtsTruth oxtsGroundTruth(const KittiRawImport& opt, const std::vector<KittiFrameFiles>& frames, ImportSummary& summary)
{
	const std::string oxts = (fs::path(opt.drive) / "oxts").string();
	const std::string imu_to_velo = (fs::path(opt.calib) / "calib_imu_to_velo.txt").string();
	if (!fs::is_directory(oxts + "/data")) return {};
	if (!fs::exists(imu_to_velo))
	{
		summary.warnings.push_back(imu_to_velo + ": not found, no ground truth written from oxts/");
		return {};
	}
	const auto times = readKittiRawTimestamps(oxts + "/timestamps.txt");
	std::vector<OxtsRecord> records;
	std::vector<double> t;
	for (const auto& f : frames)
	{
		if (f.index >= times.size())
			failInput(oxts + "/timestamps.txt", "has " + std::to_string(times.size()) + " lines, frame " + std::to_string(f.index) + " has none");
		char name[32];
		std::snprintf(name, sizeof name, "%010zu.txt", f.index);
		records.push_back(readOxtsRecord(oxts + "/data/" + name));
		t.push_back(times[f.index]);
	}
	const Eigen::Isometry3d velo_T_imu = readKittiImuToVelo(imu_to_velo);
	OxtsTruth truth{velodyneTrajectory(oxtsPoses(records), t, velo_T_imu), {}};
	const auto dead_reckoned = oxtsDeadReckonedPoses(records, t);
	if (dead_reckoned.empty()) summary.warnings.push_back(oxts + ": records without velocities or with times that do not increase, no " + velocityTruthPathFor(opt.out) + " written");
	else truth.velocities = velodyneTrajectory(dead_reckoned, t, velo_T_imu);
	return truth;
}
}  // namespace

ImportSummary importKittiRaw(const KittiRawImport& opt)
{
	const auto start = SteadyClock::now();
	ImportSummary summary;
	summary.rawlog = opt.out;
	const int camera = chooseCamera(opt.camera, (fs::path(opt.drive) / "image_0").string());
	if (camera < 0 || camera > 3) failInput("--camera", "must be 0, 1, 2 or 3");
	const std::string X = "0" + std::to_string(camera);
	const auto calib = readKittiRawCalib(
		(fs::path(opt.calib) / "calib_cam_to_cam.txt").string(), (fs::path(opt.calib) / "calib_velo_to_cam.txt").string(),
		camera);
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
	// The sweeps' own stamps, when the drive has both: each point's time from its azimuth.
	auto t_start = lidar ? timesIfPresent(velo_dir + "/timestamps_start.txt", scans.rbegin()->first) : std::vector<double>{};
	auto t_end = lidar ? timesIfPresent(velo_dir + "/timestamps_end.txt", scans.rbegin()->first) : std::vector<double>{};
	const bool sweep_stamps = !t_start.empty() && !t_end.empty() && fs::exists(velo_dir + "/timestamps.txt");
	if (lidar && !sweep_stamps)
		summary.warnings.push_back(velo_dir + ": no timestamps_start.txt / timestamps_end.txt / timestamps.txt, scans written "
											  "without point times ([lidar] point_times = auto takes them from the azimuth)");

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
		f.motion_compensated = false;  // KITTI raw: sweeps as the scanner gave them
		if (!f.scan.empty() && sweep_stamps) f.sweep = sweepOf(f.index, f.t_scan, t_start, t_end, velo_dir);
		frames.push_back(f);
	}
	if (missing_scans > 0)
		summary.warnings.push_back(velo_dir + "/data: " + std::to_string(missing_scans) + " frames have no scan");

	// Read the ground truth before writing anything, so that a bad record leaves no output.
	const OxtsTruth gt = oxtsGroundTruth(opt, frames, summary);

	SensorRig rig;
	rig.has_camera = true;
	rig.camera = calib.camera_intrinsics;
	rig.vehicle_T_camera = calib.camera_T_velo.inverse();
	rig.has_lidar = lidar;
	writeKittiFrames(frames, rig, calib.cam0_T_velo.inverse(), opt.camera_label, opt.lidar_label, "kitti-raw", summary);
	if (!gt.positions.empty())
	{
		summary.ground_truth = groundTruthPathFor(opt.out);
		writeTum(summary.ground_truth, gt.positions);
	}
	if (!gt.velocities.empty())
	{
		summary.velocity_truth = velocityTruthPathFor(opt.out);
		writeTum(summary.velocity_truth, gt.velocities);
	}
	summary.seconds = msSince(start) / 1000.0;
	return summary;
}
}  // namespace vlo::io
