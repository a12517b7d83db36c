#pragma once
// The same frames in the KITTI odometry layout, with KITTI's conventions:
//   DIR/sequences/00/image_0/NNNNNN.png  gray camera-0 images
//   DIR/sequences/00/velodyne/NNNNNN.bin float32 x y z reflectance, LiDAR ("velodyne") frame
//   DIR/sequences/00/calib.txt           P0..P3 (3x4), Tr = cam0_T_velodyne (3x4)
//   DIR/sequences/00/times.txt           seconds, one per frame
//   DIR/poses/00.txt                     camera-0 poses relative to camera 0 at frame 0 (3x4)
// Written into DIR.partial and moved into place by commit().
#include <vlo/core/frame.h>
#include <vlo/io/trajectory.h>

#include <string>

namespace vlo::sim
{
class KittiExporter
{
   public:
	/// DIR must not exist, be empty, or hold an earlier vlo-sim export (it is replaced on commit).
	KittiExporter(std::string dir, const SensorRig& rig, const std::string& description);
	~KittiExporter();
	KittiExporter(const KittiExporter&) = delete;
	KittiExporter& operator=(const KittiExporter&) = delete;

	void write(const Frame& f);
	/// Writes calib.txt, times.txt and poses/00.txt from the vehicle ground truth and moves DIR into place.
	void commit(const Trajectory& vehicle_gt);

	/// Tr of calib.txt for a rig: maps LiDAR coordinates to camera-0 coordinates.
	static Eigen::Isometry3d cam0TVelo(const SensorRig& rig);

   private:
	std::string dir_, partial_;
	SensorRig rig_;
	bool committed_ = false;
};
}  // namespace vlo::sim
