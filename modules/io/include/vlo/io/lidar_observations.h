#pragma once
// LiDAR scans as MRPT observations. vlo writes a scan without per-point time or ring as a
// CObservationPointCloud (CPointsMapXYZI) and one with them as a CObservationVelodyneScan whose
// point_cloud is filled (MRPT 2.5's only class with per-point time and laser id; it keeps intensity
// as 8 bits and point times to 1 us, so intensities are rounded into 0..255 there). It reads both, a CObservationPointCloud of
// any points map, and raw Velodyne packets (decoded with MRPT's generatePointCloud, with the calibration
// the observation carries, or MRPT's default for the model the packets name: VLP-16 or HDL-32E).
#include <vlo/core/frame.h>

#include <mrpt/obs/CObservation.h>

#include <cstddef>
#include <string>

namespace vlo::io
{
/// Observation of frame.scan (stamped frame.t) with the rig's LiDAR pose.
mrpt::obs::CObservation::Ptr toScanObservation(const Frame& frame, const std::string& label);

/// A decoded scan: points in the LiDAR frame, per-point time relative to the observation's stamp.
struct ScanReading
{
	PointCloud points;
	std::size_t dropped = 0;  ///< points with a non-finite coordinate
	/// Velodyne packets decoded with the model's default calibration (none carried, or a wrong one).
	bool default_calibration = false;
};

/// True for the classes readScanObservation reads.
bool isScanObservation(const mrpt::obs::CObservation& obs);

/// Decodes a LiDAR observation of a supported class (see above). Throws InputError(where, ...) naming
/// the class when it is not supported, or when it carries no points it could give.
ScanReading readScanObservation(mrpt::obs::CObservation& obs, const std::string& where);

/// Renumbers the rings of a scan that has them so that 0 is the lowest beam (mean elevation per id),
/// whatever order the driver numbered its lasers in: ids already bottom-up are kept, top-down ids
/// (Ouster) are flipped (both keep gaps of lasers without returns), interleaved ids are ranked.
void orderRingsByElevation(PointCloud& cloud);
}  // namespace vlo::io
