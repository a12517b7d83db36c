#include "targets.h"

#include <vlo/core/error.h>
#include <vlo/io/kitti_calib.h>
#include <vlo/io/kitti_files.h>
#include <vlo/io/rawlog_reader.h>
#include <vlo/io/trajectory.h>

#include <cmath>
#include <stdexcept>

namespace vlo::fuzz
{
namespace
{
// What a reader returns must be usable: a garbage value read without a word is a bug too.
void expect(bool ok, const std::string& what)
{
	if (!ok) throw std::logic_error("read without error but " + what);
}

bool isRigid(const Eigen::Isometry3d& T)
{
	const Eigen::Matrix3d R = T.linear();
	return T.matrix().allFinite() && (R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-6 &&
		R.determinant() > 0;
}

bool isCamera(const PinholeCamera& c)
{
	return c.valid() && std::isfinite(c.fx) && std::isfinite(c.fy) && std::isfinite(c.cx) && std::isfinite(c.cy);
}

void expectIncreasing(const std::vector<double>& times)
{
	for (std::size_t i = 0; i < times.size(); ++i)
		expect(std::isfinite(times[i]) && (i == 0 || times[i] > times[i - 1]), "times are not finite and increasing");
}

void expectFinite(const PointCloud& cloud)
{
	for (const auto& p : cloud)
		expect(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.intensity) &&
				std::isfinite(p.time),
			"a point is not finite");
}

void readAllFrames(const std::string& path, io::RawlogReaderOptions opt)
{
	io::RawlogReader reader(path, opt);
	Frame frame;
	std::vector<double> times;
	while (reader.next(frame))
	{
		times.push_back(frame.t);
		if (frame.has_image)
		{
			expect(isCamera(frame.rig.camera), "a frame's camera is not valid");
			expect(int(frame.image.getWidth()) == frame.rig.camera.width && int(frame.image.getHeight()) == frame.rig.camera.height,
				"an image's size differs from its camera's");
			expect(isRigid(frame.rig.vehicle_T_camera), "the camera pose is not a rigid transform");
		}
		if (frame.has_scan)
		{
			expectFinite(frame.scan);
			expect(isRigid(frame.rig.vehicle_T_lidar), "the LiDAR pose is not a rigid transform");
		}
	}
	expectIncreasing(times);
}

void readVelodyneRawlog(const std::string& path)
{
	io::RawlogReaderOptions opt;
	opt.lidar_label = "Velodyne1_SCAN";  // the label of MRPT's own sample recordings
	opt.need_camera = false;
	readAllFrames(path, opt);
}

void readOdometryCalib(const std::string& path)
{
	for (const int camera : {0, 2})
	{
		const auto c = io::readKittiOdometryCalib(path, camera);
		expect(c.P.allFinite() && c.P0.allFinite(), "a projection is not finite");
		expect(isRigid(c.cam0_T_velo), "Tr is not a rigid transform");
		expect(io::offsetOf(c.P).allFinite(), "the camera offset is not finite");
	}
}

// The seed holds calib_cam_to_cam.txt and calib_velo_to_cam.txt in one file: each reader takes its keys.
void readRawCalib(const std::string& path)
{
	const auto c = io::readKittiRawCalib(path, path, 2);
	expect(isCamera(c.camera_intrinsics), "the camera is not valid");
	expect(isRigid(c.camera_T_velo), "camera_T_velo is not a rigid transform");
}

void readTimes(const std::string& path) { expectIncreasing(io::readKittiTimes(path)); }
void readRawTimestamps(const std::string& path) { expectIncreasing(io::readKittiRawTimestamps(path)); }

void expectPoses(const Trajectory& traj)
{
	std::vector<double> times;
	for (const auto& p : traj)
	{
		expect(isRigid(p.pose), "a pose is not a rigid transform");
		times.push_back(p.t);
	}
	expectIncreasing(times);
}

void readPoses(const std::string& path) { expectPoses(io::readKittiPoses(path)); }

void readVelodyneBin(const std::string& path)
{
	PointCloud cloud;
	io::readKittiBin(path, cloud);
	expectFinite(cloud);
}
}  // namespace

void readRawlogChecked(const std::string& path) { readAllFrames(path, {}); }
void readTumChecked(const std::string& path) { expectPoses(io::readTum(path)); }

std::vector<Target> ioTargets()
{
	return {
		{"rawlog", "input.rawlog", readRawlogChecked},
		{"rawlog_velodyne", "input.rawlog", readVelodyneRawlog},
		{"kitti_calib", "calib.txt", readOdometryCalib},
		{"kitti_raw_calib", "calib_cam_to_cam.txt", readRawCalib},
		{"kitti_times", "times.txt", readTimes},
		{"kitti_raw_timestamps", "timestamps.txt", readRawTimestamps},
		{"kitti_poses", "poses.txt", readPoses},
		{"kitti_bin", "0000000000.bin", readVelodyneBin},
		{"tum", "trajectory.tum", readTumChecked},
	};
}
}  // namespace vlo::fuzz
