// vlo-import: converts datasets into vlo rawlogs (observation-only, CAMERA + LIDAR).
#include <vlo/core/app_main.h>
#include <vlo/core/app_cli.h>
#include <vlo/core/build_info.h>
#include <vlo/core/error.h>
#include <vlo/core/log.h>
#include <vlo/io/kitti_import.h>
#include <vlo/io/rawlog_writer.h>
#include <vlo/rosbag/rosbag_import.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

namespace
{
const char* kApp = "vlo-import";

const char* kTopUsage =
	"Usage: vlo-import <subcommand> [options]\n"
	"Converts a dataset into an MRPT rawlog for vlo (images as PNG in <name>_Images/).\n\n"
	"Subcommands:\n"
	"  kitti-odometry   KITTI odometry benchmark layout (sequences/NN, poses/NN.txt)\n"
	"  kitti-raw        KITTI raw data layout (one drive, calibration of its date)\n"
	"  rosbag           ROS 1 bags: PointCloud2 + Image/CompressedImage + CameraInfo (+ tf, ground truth)\n\n"
	"Run 'vlo-import <subcommand> --help' for its options; 'vlo-import --version' for the version.\n";

/// A subcommand's options followed by those every subcommand has: the sensor labels in the rawlog, --overwrite.
std::vector<vlo::CliOption> withCommonOptions(std::vector<vlo::CliOption> options)
{
	options.push_back({"camera-label", "L", "sensor label of the images (default CAMERA)"});
	options.push_back({"lidar-label", "L", "sensor label of the scans (default LIDAR)"});
	options.push_back({"overwrite", "", "replace an earlier import's FILE.rawlog, FILE_Images/, FILE.gt.tum and FILE.gt_velocity.tum"});
	return options;
}

/// The labels, and the output checked: like vlo-run, no earlier result is replaced without --overwrite.
template <class Import>
void readCommon(const vlo::CommandLine& cl, Import& opt)
{
	opt.camera_label = cl.get("camera-label", opt.camera_label);
	opt.lidar_label = cl.get("lidar-label", opt.lidar_label);
	if (cl.has("overwrite")) return;
	for (const std::string& p : {opt.out, vlo::io::rawlogImagesDir(opt.out), vlo::io::groundTruthPathFor(opt.out),
			 vlo::io::velocityTruthPathFor(opt.out)})
		if (std::filesystem::exists(p)) vlo::failInput(p, "exists: give --overwrite to replace it, or another --out");
}

void report(const vlo::io::ImportSummary& s)
{
	for (const auto& w : s.warnings) vlo::logger().logStr(mrpt::system::LVL_WARN, w);
	std::printf("vlo-import: %s: %zu frames (%zu images, %zu scans) in %.1f s (%.1f frames/s)\n", s.rawlog.c_str(), s.frames,
		s.images, s.scans, s.seconds, s.seconds > 0 ? s.frames / s.seconds : 0.0);
	if (!s.ground_truth.empty()) std::printf("vlo-import: %s: ground truth, vehicle frame\n", s.ground_truth.c_str());
	if (!s.velocity_truth.empty())
		std::printf("vlo-import: %s: the same truth dead-reckoned from its velocities (lengths, steps)\n", s.velocity_truth.c_str());
}

int kittiOdometry(int argc, char** argv)
{
	const vlo::CommandLine cl = vlo::parseAppCommandLine(argc, argv, 2,
		withCommonOptions({{"root", "DIR", "dataset root holding sequences/ and poses/", true},
			{"seq", "NN", "sequence number as in the folder name, e.g. 06", true},
			{"out", "FILE.rawlog", "output rawlog; ground truth goes to FILE.gt.tum", true},
			{"first", "I", "first frame (default 0)"}, {"last", "J", "last frame, inclusive (default: the last)"},
			{"camera", "X", "camera 0..3: image_X with PX (default: 0 grey, else 2 left colour, the first there; colour is stored grayscale)"}}),
		"Usage: vlo-import kitti-odometry --root ROOT --seq NN --out FILE.rawlog [options]\n"
		"Camera X (image_X, PX) + Velodyne; vehicle frame = Velodyne frame. Without velodyne/ or\n"
		"without Tr in calib.txt the rawlog is camera-only (with a warning).");
	vlo::io::KittiOdometryImport opt;
	opt.root = cl.get("root");
	opt.seq = cl.get("seq");
	opt.out = cl.get("out");
	opt.first = cl.getInt("first", 0);
	opt.last = cl.getInt("last", -1);
	if (cl.has("camera")) opt.camera = static_cast<int>(cl.getInt("camera", 0));
	readCommon(cl, opt);
	report(vlo::io::importKittiOdometry(opt));
	return 0;
}

int kittiRaw(int argc, char** argv)
{
	const vlo::CommandLine cl = vlo::parseAppCommandLine(argc, argv, 2,
		withCommonOptions({{"drive", "DIR", "drive folder holding image_0X/data and velodyne_points/data", true},
			{"calib", "DIR", "folder holding calib_cam_to_cam.txt and calib_velo_to_cam.txt", true},
			{"out", "FILE.rawlog", "output rawlog", true},
			{"camera", "X", "camera 0..3 (default: 0 grey, else 2 left colour, the first there; colour is stored grayscale)"}}),
		"Usage: vlo-import kitti-raw --drive DIR --calib DIR --out FILE.rawlog [options]\n"
		"Rectified camera X + Velodyne; projection P_rect_0X * R_rect_00 * Tr_velo_to_cam.\n"
		"Times from image_0X/timestamps.txt and velodyne_points/timestamps.txt, else 10 Hz from 0.");
	vlo::io::KittiRawImport opt;
	opt.drive = cl.get("drive");
	opt.calib = cl.get("calib");
	opt.out = cl.get("out");
	if (cl.has("camera")) opt.camera = static_cast<int>(cl.getInt("camera", 0));
	readCommon(cl, opt);
	report(vlo::io::importKittiRaw(opt));
	return 0;
}
int rosbag(int argc, char** argv)
{
	const vlo::CommandLine cl = vlo::parseAppCommandLine(argc, argv, 2,
		withCommonOptions({{"bag", "FILE.bag", "input bag (repeat for a recording split into several bags)", true, true},
			{"list", "", "print every topic with its type, message count and rate, and stop"},
			{"lidar-topic", "TOPIC", "sensor_msgs/PointCloud2 topic"},
			{"image-topic", "TOPIC", "sensor_msgs/Image or sensor_msgs/CompressedImage topic"},
			{"camera-info-topic", "TOPIC", "sensor_msgs/CameraInfo (default: .../camera_info next to the image topic)"},
			{"camera-info", "FILE.yaml", "camera calibration file (ROS camera_calibration format) for bags without CameraInfo"},
			{"extrinsics", "FILE.yaml", "lidar_T_camera: [16 numbers], row-major (default: from /tf_static, /tf)"},
			{"gt-topic", "TOPIC", "nav_msgs/Odometry, geometry_msgs/PoseStamped or PointStamped -> FILE.gt.tum"},
			{"vehicle-frame", "FRAME", "tf frame to use as vehicle frame (default: the LiDAR's frame)"},
			{"reorder-window", "S", "seconds of header stamps held to sort messages (default 1)"},
			{"out", "FILE.rawlog", "output rawlog"}}),
		"Usage: vlo-import rosbag --bag FILE.bag [--bag MORE.bag ...] --list\n"
		"       vlo-import rosbag --bag FILE.bag [--bag ...] --lidar-topic TOPIC --image-topic TOPIC\n"
		"                         [--camera-info-topic TOPIC | --camera-info FILE.yaml] [--extrinsics FILE.yaml]\n"
		"                         [--gt-topic TOPIC] [--vehicle-frame FRAME] [--reorder-window S]\n"
		"                         [--camera-label L] [--lidar-label L] [--overwrite] --out FILE.rawlog\n"
		"Messages are written in header-stamp order with their own stamps; see doc/ROSBAG.md.");
	if (cl.has("list"))
	{
		vlo::rosbag_io::listRosbagTopics(cl.getAll("bag"), std::cout);
		return 0;
	}
	for (const char* required : {"lidar-topic", "image-topic", "out"})
		if (!cl.has(required)) vlo::failInput("command line", std::string("missing required option '--") + required + "'");
	vlo::rosbag_io::RosbagImport opt;
	opt.bags = cl.getAll("bag");
	opt.lidar_topic = cl.get("lidar-topic");
	opt.image_topic = cl.get("image-topic");
	opt.camera_info_topic = cl.get("camera-info-topic");
	opt.camera_info_file = cl.get("camera-info");
	opt.extrinsics = cl.get("extrinsics");
	opt.gt_topic = cl.get("gt-topic");
	opt.vehicle_frame = cl.get("vehicle-frame");
	opt.reorder_window = cl.getDouble("reorder-window", opt.reorder_window);
	opt.out = cl.get("out");
	readCommon(cl, opt);
	const auto s = vlo::rosbag_io::importRosbag(opt);
	for (const auto& w : s.warnings) vlo::logger().logStr(mrpt::system::LVL_WARN, w);
	const double mb = s.bag_bytes / 1e6;
	std::printf("vlo-import: %s: %zu images, %zu scans (%zu non-finite points dropped), extrinsics from %s; %.1f MB of bags in %.1f s (%.1f MB/s)\n",
		s.rawlog.c_str(), s.images, s.scans, s.dropped_points, s.extrinsics_source.c_str(), mb, s.seconds,
		s.seconds > 0 ? mb / s.seconds : 0.0);
	if (!s.ground_truth.empty()) std::printf("vlo-import: %s: %zu ground-truth poses, vehicle frame\n", s.ground_truth.c_str(), s.gt_poses);
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	return vlo::runApp(kApp, [&] {
		const std::string sub = argc > 1 ? argv[1] : "";
		if (sub == "--help" || sub == "-h")
		{
			std::cout << kTopUsage;
			return 0;
		}
		if (sub == "--version")
		{
			std::cout << vlo::versionLine(kApp) << "\n";
			return 0;
		}
		if (sub == "kitti-odometry") return kittiOdometry(argc, argv);
		if (sub == "kitti-raw") return kittiRaw(argc, argv);
		if (sub == "rosbag") return rosbag(argc, argv);
		vlo::failInput("command line",
			sub.empty() ? "missing subcommand (kitti-odometry, kitti-raw or rosbag; see --help)" : "unknown subcommand '" + sub + "' (see --help)");
	});
}
