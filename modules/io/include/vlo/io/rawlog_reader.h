#pragma once
// Streaming reader of MRPT rawlogs (observation-only and action/sensory-frame formats) that pairs
// camera and LiDAR observations into synchronized frames by timestamp. Never loads the whole file:
// it buffers at most a few observations per sensor.
#include <vlo/core/frame.h>

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace vlo::io
{
struct RawlogReaderOptions
{
	std::string camera_label = "CAMERA";
	std::string lidar_label = "LIDAR";
	double max_time_diff = 0.05;  ///< seconds between a paired image and scan
	bool need_camera = true;  ///< false: frames may lack an image (LiDAR-only runs)
	bool need_lidar = true;  ///< false: frames may lack a scan (camera-only runs)
	/// Observations held per sensor while waiting for a partner; beyond this the oldest is
	/// given up as unpaired (bounds memory when one sensor is missing or far out of step).
	std::size_t max_pending = 20;
};

struct RawlogStats
{
	std::size_t observations = 0;  ///< all observations read
	std::size_t frames = 0;  ///< frames returned
	std::size_t unpaired_images = 0, unpaired_scans = 0;  ///< dropped for lack of a partner
	std::size_t other_labels = 0;  ///< observations with neither label
	std::size_t invalid_points = 0;  ///< NaN/inf LiDAR points removed
	std::size_t default_calibrations = 0;  ///< Velodyne scans decoded with their model's default calibration
	std::map<std::string, std::size_t> labels;  ///< observations per sensor label
};

class RawlogReader
{
   public:
	/// Throws InputError if the file is missing or is not a rawlog. Images stored externally are
	/// looked up in "<dir>/<name>_Images/" (name = file name without extension).
	explicit RawlogReader(const std::string& path, RawlogReaderOptions options = {});
	~RawlogReader();
	RawlogReader(const RawlogReader&) = delete;
	RawlogReader& operator=(const RawlogReader&) = delete;

	/// Fills the next frame (index counts from 0; t in seconds as stored); false at the end of the
	/// file. Throws InputError naming the file for a corrupt or truncated file, timestamps out of
	/// order, a wrong image size, or (at the end) when a needed sensor label never appeared (the
	/// message lists the labels seen) or nothing could be paired.
	bool next(Frame& frame);
	const RawlogStats& stats() const;
	/// KITTI's camera 0 on the vehicle, once the rawlog's note of it has been read (KITTI imports).
	const std::optional<Eigen::Isometry3d>& vehicleTCamera0() const;
	/// One line: "N frames; M images and K scans without partner; ..." for logs.
	std::string statsSummary() const;
	/// Fraction of the file read so far (for progress lines).
	double progress() const;

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};
}  // namespace vlo::io
