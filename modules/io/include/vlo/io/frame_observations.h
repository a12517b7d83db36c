#pragma once
// Conversion between vlo's Frame/SensorRig and MRPT observations, following DESIGN.md:
// CObservationImage::cameraPose = optical frame in the vehicle frame, cameraParams = intrinsics with the
// lens distortion; scans (see lidar_observations.h) with sensorPose = LiDAR in vehicle.
#include <vlo/core/frame.h>

#include <mrpt/img/TCamera.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationImage.h>

#include <cstddef>
#include <string>

namespace vlo::io
{
/// Seconds (as in the dataset) <-> MRPT timestamps, rounded to MRPT's 100 ns ticks (MRPT's own
/// Clock::fromDouble truncates, which loses a tick on values like KITTI's 0.3116343).
mrpt::Clock::time_point toTimestamp(double seconds);
double toSeconds(const mrpt::Clock::time_point& t);

/// Image observation of frame.image with the rig's camera (image kept inline).
mrpt::obs::CObservationImage::Ptr toImageObservation(const Frame& frame, const std::string& label);

mrpt::img::TCamera toTCamera(const PinholeCamera& cam);
/// Throws InputError(where, ...) for invalid intrinsics, a non-finite distortion coefficient or an
/// unknown distortion model.
PinholeCamera fromTCamera(const mrpt::img::TCamera& params, const std::string& where);

/// KITTI's camera 0 travels in the rawlog as a text observation (CObservationComment, which MRPT stores
/// without a sensor label), written once ahead of the first frame: "vehicle_T_camera0 (row-major 3x4): 12 numbers".
mrpt::obs::CObservationComment::Ptr toCamera0Note(const Eigen::Isometry3d& vehicle_T_camera0, double t);
/// True for a comment that is such a note.
bool isCamera0Note(const mrpt::obs::CObservationComment& comment);
/// Throws InputError(where, ...) when the note holds no rigid transform.
Eigen::Isometry3d camera0FromNote(const mrpt::obs::CObservationComment& note, const std::string& where);

/// Grayscale version of an image (no copy when it already is).
mrpt::img::CImage toGray(const mrpt::img::CImage& img);
}  // namespace vlo::io
